#include "renderer/app/panel_figure.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "renderer/image/display_image.h"
#include "renderer/image/image_output.h"
#include "renderer/image/text.h"
#include "renderer/library/hyperstreamball.h"
#include "renderer/library/picture_output.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/render/render_image.h"

namespace hsb {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string panel_letter(std::size_t i) { return std::string("(") + char('a' + int(i)) + ")"; }

// Each panel's scene: the figure's with the panel's keys, errors naming the
// panel.
SceneSpec panel_scene(const SceneSpec& figure, const PanelSpec& panel, std::size_t index,
                      const std::vector<std::string>& extra) {
  std::vector<std::string> overrides = figure.overrides;
  overrides.insert(overrides.end(), panel.overrides.begin(), panel.overrides.end());
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  try {
    return load_scene_text(figure.text, figure.path, figure.base_dir, overrides);
  } catch (const SceneError& e) {
    throw SceneError(figure.path + ":" + std::to_string(panel.line) + ": panel " + panel_letter(index) + ": " +
                     e.what());
  }
}

// The range every panel shares: their own if all give the same one, else
// the automatic range over all their glyphs.
ColorScale shared_scale(const std::vector<std::unique_ptr<PreparedScene>>& panels) {
  const PreparedScene& first = *panels.front();
  const bool all_given = std::all_of(panels.begin(), panels.end(), [&](const auto& p) {
    return p->spec.color.range && *p->spec.color.range == *first.spec.color.range;
  });
  std::vector<double> values, reach;  // the glyphs' colour values; those the range spans
  for (const auto& p : panels) {
    for (const GlyphSource& s : p->glyphs.sources) values.push_back(s.scalar);
    const std::vector<double> spanned = color_range_values(p->glyphs);
    reach.insert(reach.end(), spanned.begin(), spanned.end());
  }
  const ColorSpec& c = first.spec.color;
  ColorScale scale = all_given ? first.scale
                               : auto_scale(*first.scale.map, reach, c.symmetric.value_or(first.scale.map->diverging), c.log);
  record_extremes(scale, values);
  return scale;
}

bool share_colour_bar(const std::vector<std::unique_ptr<PreparedScene>>& panels) {
  const PreparedScene& first = *panels.front();
  return std::all_of(panels.begin(), panels.end(), [&](const auto& p) {
    return p->glyphs.color == first.glyphs.color && p->scale.map == first.scale.map &&
           p->spec.color.log == first.spec.color.log &&
           p->spec.pipeline.data.file.color_array == first.spec.pipeline.data.file.color_array &&
           p->spec.color.range.has_value() == first.spec.color.range.has_value();
  });
}

}  // namespace

int panel_columns(int panels, int width, int height, std::optional<int> columns) {
  if (columns) return std::clamp(*columns, 1, panels);
  int best = 1;
  double best_error = INFINITY;
  for (int c = 1; c <= panels; ++c) {
    const int rows = (panels + c - 1) / c;
    const double aspect = (double(width) / c) / (double(height) / rows);
    const double error = std::fabs(std::log(aspect));
    if (error < best_error - 1e-9) best = c, best_error = error;
  }
  return best;
}

RenderSummary render_panel_figure(SceneSpec figure, const std::string& image_path,
                                  const std::function<void(JobStage, double)>& progress) {
  const auto start = Clock::now();
  const auto report = [&](JobStage stage, double fraction) {
    if (progress) progress(stage, fraction);
  };
  if (is_scene_linear_format(image_path))
    throw SceneError(figure.path + ": a figure of panels is written as PNG, TIFF, PDF or SVG, not EXR "
                                   "(render the panels as scenes of their own for compositing)");
  const std::array<int, 2> size = picture_size(figure);
  const int width = size[0], height = size[1];
  const std::size_t n = figure.panels.size();
  const int columns = panel_columns(int(n), width, height, figure.figure.columns);
  const int rows = (int(n) + columns - 1) / columns;
  const ColorManagement color = scene_color_management(figure);

  // The text: labels at each panel's top left, the caption under all.
  const double point = legend_pixels_per_point(figure.output.dpi, width, height);
  const double font = figure.output.font_size * point;
  double caption_height = 0.0;
  if (!figure.figure.caption.empty()) {
    double w, h;
    text_size(measuring_context().get(), figure.figure.caption, font, w, h);
    caption_height = h * std::ceil(w / (0.9 * width)) + 2.0 * font;
  }

  // First with a colour bar each, at the size a panel would have beside a
  // shared bar as wide as a single picture's: whether they share one can
  // only be said once their glyphs exist.
  std::vector<std::unique_ptr<PreparedScene>> panels;
  const auto prepare = [&](int panel_width, int panel_height, bool own_bar) {
    // What the figure leaves each panel: too little is the figure's
    // fault, not a --set the user never typed.
    constexpr int smallest = 4;
    if (panel_width < smallest || panel_height < smallest)
      throw SceneError(figure.path + ": " + std::to_string(n) + " panels of a " + std::to_string(width) + "×" +
                       std::to_string(height) + " picture" + (caption_height > 0.0 ? " with its caption" : "") +
                       (own_bar ? "" : " and a shared colour bar") + " get " + std::to_string(panel_width) + "×" +
                       std::to_string(panel_height) + " pixels each, less than " + std::to_string(smallest) +
                       ": enlarge render.width and render.height (or output.print_size), use fewer panels or a "
                       "shorter figure.caption");
    panels.clear();
    for (std::size_t i = 0; i < n; ++i) {
      SceneSpec spec = panel_scene(figure, figure.panels[i], i,
                                   {"render.width=" + std::to_string(panel_width),
                                    "render.height=" + std::to_string(panel_height),
                                    std::string("output.colorbar=") + (own_bar ? "true" : "false")});
      panels.push_back(prepare_scene(std::move(spec), color));
    }
  };
  const int area_height = std::max(1, int(height - caption_height));
  const bool bars = figure.output.colorbar;
  prepare(width / columns, area_height / rows, bars);
  const bool shared = bars && share_colour_bar(panels);
  double reserved_right = 0.0, reserved_bottom = 0.0;
  std::optional<LegendLayout> bar;
  if (shared) {
    const ColorScale scale = shared_scale(panels);
    set_color_scale(*panels.front(), scale, color);
    bar = legend_for(*panels.front(), width, area_height);
    (bar->style.placement == LegendPlacement::right ? reserved_right : reserved_bottom) = bar->reserved;
    const int panel_width = int(width * (1.0 - reserved_right)) / columns;
    const int panel_height = int(area_height * (1.0 - reserved_bottom)) / rows;
    prepare(panel_width, panel_height, false);
    for (auto& p : panels) set_color_scale(*p, scale, color);
  }

  // Each panel rendered, made display-referred and placed in the figure.
  const bool transparent = panels.front()->shading.background_kind == BackgroundKind::transparent;
  // Between and around the panels, the background as the display shows it.
  std::vector<float> background{0, 0, 0, 1};
  const Rgb linear = color.to_scene_linear(figure.shading.background);
  std::copy(linear.begin(), linear.end(), background.begin());
  color.apply_display(background, 1, 1);
  std::vector<float> rgba(std::size_t(width) * std::size_t(height) * 4, 0.0f);
  if (!transparent)
    for (std::size_t i = 0; i < rgba.size(); i += 4) std::copy(background.begin(), background.end(), &rgba[i]);
  Annotations annotations;
  RenderSummary summary;
  summary.build_seconds = seconds_since(start);
  double render_seconds = 0.0;
  std::ostringstream resolved;
  for (std::size_t i = 0; i < n; ++i) {
    PreparedScene& p = *panels[i];
    const int x0 = int(i % std::size_t(columns)) * p.render.width, y0 = int(i / std::size_t(columns)) * p.render.height;
    RenderControl control;
    control.progress = [&](double fraction) { report(JobStage::rendering, (double(i) + fraction) / double(n)); };
    Picture picture = render(p, control);
    RenderOutput& out = picture.rendered;
    render_seconds += out.seconds;
    const std::vector<float> panel = display_pixels(std::move(out.film), color, transparent);
    for (int y = 0; y < p.render.height; ++y)
      std::copy_n(&panel[std::size_t(y) * std::size_t(p.render.width) * 4], std::size_t(p.render.width) * 4,
                  &rgba[(std::size_t(y0 + y) * std::size_t(width) + std::size_t(x0)) * 4]);
    if (p.output.legend)
      annotations.legends.push_back({p.output.legend->shifted(x0, y0), p.scale,
                                     legend_ink(panel, p.render.width, p.render.height, *p.output.legend)});
    if (figure.figure.labels) {
      const std::string label = panel_letter(i) + (figure.panels[i].label.empty() ? "" : " " + figure.panels[i].label);
      annotations.texts.push_back({label, x0 + 4.0 * point, y0 + 3.0 * point, font, 0.0, 0.0, false, 0.0,
                                   ink_over(panel, p.render.width, 2, 2)});
    }
    summary.sources += p.field.sources.size();
    summary.trajectories += p.glyphs.trajectories.size();
    summary.primary_rays += out.primary_rays;
    summary.shadow_rays += out.shadow_rays;
    summary.stats += out.stats;
    summary.shadow_stats += out.shadow_stats;
    for (const std::string& w : picture.warnings) summary.warnings.push_back(panel_letter(i) + " " + w);
    resolved << "# panel " << panel_letter(i) << "\n" << pinned_scene_toml(p) << "\n";
  }
  if (bar) annotations.legends.push_back({*bar, panels.front()->scale, legend_ink(rgba, width, height, *bar)});
  if (!figure.figure.caption.empty())
    annotations.texts.push_back({figure.figure.caption, 0.5 * width, height - caption_height + font, font, 0.5, 0.0,
                                 false, 0.9 * width, ink_over(rgba, width, width / 2, height - 2)});

  report(JobStage::writing, 1.0);
  const auto output_start = Clock::now();
  std::ostringstream description;
  description << n << " panels, " << summary.sources << " sources";
  OutputSettings output = panels.front()->output;
  write_display_picture(image_path, std::move(rgba), width, height, transparent, annotations, output,
                        picture_metadata(figure, description.str(), resolved.str(), color), color);
  summary.image_path = image_path;
  summary.render_seconds = render_seconds;
  summary.output_seconds = seconds_since(output_start);
  summary.total_seconds = seconds_since(start);
  return summary;
}

}  // namespace hsb
