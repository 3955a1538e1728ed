# ParaView's side of tests/bench/paraview_bench.sh: one superquadric tensor
# glyph per voxel with FA at or above a threshold, rendered by pvbatch.
#
#   pvbatch tests/bench/paraview_glyphs.py HELIX.vtk OUT.png SIZE
#           [RESOLUTION [THETA_ROUNDNESS PHI_ROUNDNESS]]
#
# HELIX.vtk is the legacy VTK file paraview_bench.sh writes from Teem's
# helix: STRUCTURED_POINTS with point arrays `tensors` (9 components,
# symmetric) and `fa`. Reader → ExtractSelection of the points with
# fa ≥ 0.3 (a Threshold would keep cells, and drop a passing point whose
# every cell has a failing corner) → TensorGlyph with a superquadric source
# → one render at SIZE × SIZE with the camera of teem_bench.sh and hsb, on a
# magenta background, no FXAA, no orientation axes, no colour legend, one
# light. Prints `glyphs=N` (the glyphs drawn) for the bench to check.
import sys

from paraview.simple import (AddLight, ExtractSelection, GetActiveViewOrCreate, LegacyVTKReader,
                             SaveScreenshot, SelectionQuerySource, Show, TensorGlyph)

path, png, size = sys.argv[1], sys.argv[2], int(sys.argv[3])
resolution = int(sys.argv[4]) if len(sys.argv) > 4 else 16
# Kindlmann's superquadric (and hsb's and Teem's) takes its exponents from
# each tensor's Westin measures: a linear glyph (c_l > c_p, every glyph of
# the helix) is round about its major axis with the equatorial exponent
# α = (1 − c_p)^γ and the axial one β = (1 − c_l)^γ, γ the sharpness (3).
# ParaView's source has one fixed pair for every glyph: ThetaRoundness is
# the equatorial exponent α, PhiRoundness the axial β (0 square, 1 round).
# A strongly linear tensor (c_l → 1) would give α = 1, β → 0; the helix's
# tensors are only moderately linear (c_l 0.17–0.44, c_p 0.08–0.22, 5th to
# 95th percentile of the glyphs drawn), and its median glyph (c_l 0.33,
# c_p 0.16) gives α ≈ 0.58, β ≈ 0.30: those are the defaults, the typical
# glyph's shape (at 2000², α = 1, β = 0.05 agrees with hsb's mask on
# 0.99933 of the pixels, these on 0.99952).
theta_roundness = float(sys.argv[5]) if len(sys.argv) > 5 else 0.58
phi_roundness = float(sys.argv[6]) if len(sys.argv) > 6 else 0.30
threshold, scale = 0.3, 150.0  # as hsb's region.above and glyphs.scale

reader = LegacyVTKReader(FileNames=[path])
query = SelectionQuerySource(ElementType='Point Data', QueryString='fa >= %r' % threshold)
kept = ExtractSelection(Input=reader, Selection=query)

glyphs = TensorGlyph(Input=kept, GlyphType='Superquadric')
glyphs.Tensors = ['POINTS', 'tensors']
glyphs.Scalars = ['POINTS', 'fa']
glyphs.ExtractEigenvalues = 1          # semi-axes along the eigenvectors, scaled by the eigenvalues
glyphs.LimitScalingByEigenvalues = 0   # no clamping of the eigenvalues
glyphs.ColorGlyphs = 0
glyphs.Symmetric = 0                   # no mirrored second glyph
source = glyphs.GlyphType
source.Toroidal = 0                    # ParaView's default is a torus
source.ThetaResolution = resolution
source.PhiResolution = resolution
source.ThetaRoundness = theta_roundness
source.PhiRoundness = phi_roundness
# vtkTensorGlyph scales the source by ScaleFactor × each eigenvalue; the
# superquadric source's half-extent is its Size (0.5, not 1), so a glyph's
# semi-axes are Size × ScaleFactor × λ: ScaleFactor = 150 / Size gives 150 λ.
glyphs.ScaleFactor = scale / source.Size
# vtkTensorGlyph puts the source's x axis on the major eigenvector (then y,
# z on the medium and minor); vtkSuperquadricSource is round about its y
# axis by default and ParaView does not expose AxisOfSymmetry, so it is set
# on the VTK object itself (pvbatch runs builtin, the object is in this
# process): round about x, the major axis, as Kindlmann's linear glyph.
source.GetClientSideObject().SetAxisOfSymmetry(0)
glyphs.UpdatePipeline()
print('glyphs=%d roundness θ %g, φ %g, %d × %d facets' % (kept.GetDataInformation().GetNumberOfPoints(),
      theta_roundness, phi_roundness, resolution, resolution), flush=True)

view = GetActiveViewOrCreate('RenderView')
view.ViewSize = [size, size]
view.OrientationAxesVisibility = 0
view.UseFXAA = 0
view.UseToneMapping = 0
view.EnableRenderOnInteraction = 0
view.UseColorPaletteForBackground = 0
view.BackgroundColorMode = 'Single Color'
view.Background = [1.0, 0.0, 1.0]      # magenta: mask_agreement's background
view.UseLight = 0                      # no light kit: one headlight instead
light = AddLight(view=view)
light.Coords = 'Headlight'         # a light at the camera, pointing at the focal point

display = Show(glyphs, view)
display.ColorArrayName = ['POINTS', '']  # one solid colour: no lookup table, no colour legend
display.DiffuseColor = [0.85, 0.85, 0.8]
display.AmbientColor = [0.85, 0.85, 0.8]

view.CameraPosition = [400.0, -600.0, 300.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30.0            # vertical, as hsb's camera.fov and Teem's -fv
view.CameraParallelProjection = 0
SaveScreenshot(png, view, ImageResolution=[size, size], TransparentBackground=0)
