# Sourced by teem_bench.sh and paraview_bench.sh: hsb's side of their
# comparison, one command for both.
#
#   helix_glyph_field HELIX OUT SIZE SHAPE
#
# sets the array `hsb` to the command that renders HELIX (Teem's `tend
# helix`) as a glyph field into OUT/hsb.png at SIZE²: one glyph per voxel
# with FA ≥ 0.3, semi-axes 150 λ (linear mapping, no floor or ceiling to
# speak of), ellipsoids or superquadrics at sharpness 3 (SHAPE), each
# its own surface (a union, blend = "max", of the quartic kernel with
# influence radius 1/√(1 − 1/√2), whose level radius at C = ½ is 1, so a
# glyph is its ellipsoid's own size), Teem's camera, one sample per pixel,
# neither shadows nor ambient occlusion (Teem draws them only when asked,
# with -shadow and -ao, ParaView's Tensor Glyph not at all), nothing but
# the glyphs on magenta (mask_agreement's background).
helix_glyph_field() {
  local helix=$1 out=$2 size=$3 shape=$4
  hsb=(./build/hsb render "$helix" -o "$out" --set 'output.file="hsb.png"'
       --set 'glyphs.placement="points"' --set glyphs.stride=1 --set region.above=0.3
       --set "glyphs.shape=\"$shape\"" --set 'glyphs.mapping="linear"' --set glyphs.scale=150
       --set glyphs.floor=0.01 --set glyphs.ceiling=inf --set 'surface.kernel="quartic"'
       --set surface.influence_radius=1.847759065 --set 'surface.blend="max"'
       --set 'camera.position=[400,-600,300]' --set 'camera.look_at=[0,0,0]' --set 'camera.up=[0,0,1]'
       --set camera.fov=30 --set render.width="$size" --set render.height="$size" --set render.samples=1
       --set light.shadows=false --set light.ambient_occlusion.samples=0 --set output.colorbar=false --set render.box=false --set render.shell=false
       --set 'render.background=[1,0,1]')
  [[ $shape == superquadric ]] && hsb+=(--set glyphs.sharpness=3)
  return 0
}
