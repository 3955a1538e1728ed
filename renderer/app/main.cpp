// hsb: the Hyperstreamball command line.

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "base/partial_file.h"
#include "base/process_memory.h"
#include "base/terminal_text.h"
#include "base/thread_room.h"
#include "field/reading/data_formats.h"
#include "field/reading/data_info.h"
#include "renderer/app/batch.h"
#include "renderer/app/export_job.h"
#include "renderer/app/render_job.h"
#include "renderer/app/scheduler_share.h"
#include "renderer/app/series_settings_file.h"
#include "renderer/image/image_io_module.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "renderer/scene/scene_error.h"
#include "renderer/scene/scene_keys.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/surface/instruction_set.h"

#ifndef HSB_VERSION
#define HSB_VERSION "unknown"
#endif

namespace {

// Ctrl-C or a scheduler's SIGTERM: stop at once, wherever the program is
// (reading data, tracing, writing an image), removing every temporary file
// first. Images only ever reach their final names complete (PartialFile),
// so an existing image at an output path stays as it was.
extern "C" void stop_on_signal(int signal) {
  hsb::remove_partial_files();
  static const char message[] = "\nhsb: interrupted; no partial file left behind\n";
  const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
  (void)ignored;
  _exit(128 + signal);
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = stop_on_signal;
  sigemptyset(&action.sa_mask);
  // Every signal that would end the program and can be caught.
  for (int signal : {SIGINT, SIGTERM, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU})
    sigaction(signal, &action, nullptr);
  // A closed pipe or a file size limit is a failed write, reported where
  // it happens, not a silent death: `hsb render ... | head` renders on.
  signal(SIGPIPE, SIG_IGN);
  signal(SIGXFSZ, SIG_IGN);
  // A hang-up stops the batch too, unless it runs under nohup.
  struct sigaction hangup {};
  if (sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN) sigaction(SIGHUP, &action, nullptr);
}

// Whether standard output is a pipe whose reader has gone (`| head`):
// the write end of such a pipe polls as an error.
bool reader_gone() {
  pollfd out{fileno(stdout), POLLOUT, 0};
  return poll(&out, 1, 0) == 1 && (out.revents & POLLERR);
}

// Whether all that was printed reached standard output; if not, `why`.
// A write that failed earlier (a summary flushed into a closed pipe) left
// only the stream's error flag, not its errno: the pipe itself tells.
bool standard_output_written(std::string& why) {
  errno = 0;
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return true;
  why = errno ? std::strerror(errno) : reader_gone() ? std::strerror(EPIPE) : "write error";
  return false;
}

// What the rays of one kind cost inside the blob field, per ray that
// reached it.
void print_trace_stats(const char* kind, const hsb::TraceStats& stats) {
  const double field_rays = double(std::max<std::uint64_t>(1, stats.field_rays));
  std::printf("  %s rays into the field %llu: per ray %.2f span queries testing %.1f influence boxes,\n"
              "    %.2f support intervals, %.2f segments, %.2f field evaluations, %.1f kernel evaluations\n",
              kind, (unsigned long long)stats.field_rays, double(stats.span_queries) / field_rays,
              double(stats.span_candidates) / field_rays, double(stats.spans) / field_rays,
              double(stats.segments) / field_rays, double(stats.field_evaluations) / field_rays,
              double(stats.kernel_evaluations) / field_rays);
}

void print_summary(const hsb::RenderSummary& s, bool with_stats) {
  for (const std::string& warning : s.warnings) std::fprintf(stderr, "hsb: warning: %s\n", hsb::shown(warning).c_str());
  const double rays = double(s.primary_rays + s.shadow_rays);
  const double mrays = s.render_seconds > 0.0 ? rays / s.render_seconds * 1e-6 : 0.0;
  std::printf("%s  sources=%zu  trajectories=%zu  time=%.2fs (build %.2fs, render %.2fs, output %.2fs)  %.2f Mrays/s\n",
              s.image_path.c_str(), s.sources, s.trajectories, s.total_seconds, s.build_seconds,
              s.render_seconds, s.output_seconds, mrays);
  if (with_stats) {
    std::printf("  primary rays %llu (%.2f Mrays/s), shadow rays %llu (%.2f Mrays/s)\n",
                (unsigned long long)s.primary_rays, s.primary_mrays_per_second,
                (unsigned long long)s.shadow_rays, s.shadow_mrays_per_second);
    print_trace_stats("camera", s.stats);
    print_trace_stats("shadow", s.shadow_stats);
    const double peak = hsb::peak_resident_bytes();
    std::printf("  peak memory %.0f MB (%.0f bytes per source, the film and program included); estimated %.0f MB\n",
                peak * 1e-6, peak / double(std::max<std::size_t>(1, s.sources)), s.memory_estimate * 1e-6);
    const std::uint64_t gave_up = s.stats.step_limit_hits + s.shadow_stats.step_limit_hits;
    if (gave_up) std::printf("  rays that hit the step limit: %llu\n", (unsigned long long)gave_up);
  }
  std::fflush(stdout);
}

// `hsb --version`: the program's, and what it traces with.
std::string version_text() {
  std::string text = std::string("hsb ") + HSB_VERSION + "\n";
  try {
    const hsb::InstructionSet isa = hsb::active_isa();
    const hsb::EmbreeDevice device;
    text += std::string("instruction set: ") + hsb::isa_name(isa) +
            (hsb::isa_forced() ? std::string(" (forced; this processor has up to ") +
                                     hsb::isa_name(hsb::best_supported_isa()) + ")"
                               : std::string(" (this processor's best)")) +
            "\n";
    text += "  " + device.describe() + "\n";
    text += std::string("  renderer: ") + hsb::isa_name(isa) + " span kernels\n";
    // Without deep binding (an allocator preloaded, a sanitizer) the image
    // module takes a tenth of a second or more longer to load.
    text += std::string("  image module: ") + (hsb::image_io_binds_deep() ? "deep-bound" : "ordinary") + " load";
  } catch (const std::runtime_error& e) {
    text += std::string("instruction set: ") + e.what();
  }
  return text;
}

// The command line's command, run to its end: every file it writes is
// complete and closed, every thread it started joined, when it returns.
int run(int argc, char** argv) {
  install_signal_handlers();
  // Arrays of a megabyte or more (a volume's values, the film, the
  // display image) get mappings of their own, returned whole when freed.
  // glibc's default raises this threshold with every such array freed (to
  // 32 MB), after which a volume's arrays, read and freed before the
  // render, stayed in the heap: Teem's helix at 2000² peaked at 279 MB
  // instead of 238 MB, at the same speed.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  CLI::App app{"Hyperstreamball " HSB_VERSION
               ": ray-traced hyperstreamballs (anisotropic metaballs along stress\n"
               "trajectories) for symmetric tensor fields."};
  app.footer(
      "Scene files are TOML; every key and its default is documented in scenes/README.md (hsb keys lists them).\n"
      "Example: hsb render scenes/fig05_point_load_linear.toml -o out --set render.width=400");
  app.set_version_flag("--version", version_text,
                       "Print the version and the instruction set in use (Embree's and the renderer's), then exit");
  app.require_subcommand(1);

  CLI::App* render = app.add_subcommand("render", "Render scene files to images, one after another.");
  std::vector<std::string> scenes;
  std::string output_dir = "out";
  std::vector<std::string> overrides;
  bool stats = false;
  render->add_option("scenes", scenes,
                     "Scene files (.toml) to render; a data file (" + hsb::readable_extensions_text() +
                         ") renders as a\nscene naming only that file, every other value automatic")
      ->required();
  render->add_option("-o,--output", output_dir,
                     "Folder for the images (created if missing); output.file is relative to it")
      ->capture_default_str();
  render->add_option("--set", overrides,
                     "Override a scene key for every scene, e.g. --set render.width=400 "
                     "--set glyphs.mapping=sqrt (the value is TOML; bare words are strings)")
      ->allow_extra_args(false);  // one value per --set, so scenes may follow it
  render->footer(
      "Prints one line per image: file, sources, trajectories, time (build, render) and Mrays/s.\n"
      "A scene that fails prints one error (file:line:column: what was expected, what was found)\n"
      "and leaves no image; the others still render, and a summary at the end lists every failure.\n"
      "Progress goes to standard error: a line updated in place on a terminal, a line every 10 s\n"
      "of a long image otherwise, nothing with --quiet.\n"
      "Sweeps: --set glyphs.spacing=0.02,0.05,0.1 renders one image per value (named after it);\n"
      "several swept keys give every combination; a scene's [sweep] table does the same.\n"
      "Ctrl-C or SIGTERM stops at once and leaves no partial file.\n"
      "Exit status: 0 when every image rendered (or was up to date) or the share held none, 1 if any\n"
      "failed, 2 for a bad --shard (or a job array --shard auto cannot share out exactly), 106-109 for\n"
      "other command-line errors, 130 after Ctrl-C, 143 after SIGTERM.");
  render->add_flag("--stats", stats,
                   "Also print ray counts, support intervals and field evaluations per ray");
  bool quiet = false, skip_existing = false, as_series = false;
  std::string shard_text;
  render->add_flag("-q,--quiet", quiet, "No progress and no line per image; warnings and errors only");
  render->add_flag("--skip-existing", skip_existing,
                   "Skip an image whose file exists and holds this scene's hash (scene text, --set values,\n"
                   "data file): a re-run batch renders only what changed");
  render->add_flag("--series", as_series,
                   "The scenes or data files given are the steps of one series (plate_050.vtu plate_100.vtu ...):\n"
                   "one glyph scale, colour range, picture size and camera for all, so a growing load shows as\n"
                   "growing glyphs in frames that do not jump, as the steps of a .pvd or Exodus file already do");
  render->add_option("--shard", shard_text,
                     "K/N: render only the K-th of N shares of the batch (item i when i mod N = K-1), e.g. 3/8.\n"
                     "auto: this job array task's share, from its scheduler's variables: Slurm, Grid Engine,\n"
                     "LSF, AWS Batch; PBS Pro, Torque and Kubernetes Indexed Jobs with HSB_SHARD_COUNT (the\n"
                     "number of tasks), HSB_SHARD_FIRST (the first index: default 0, 1 for LSF) and\n"
                     "HSB_SHARD_STEP (default 1); anything else (HTCondor) with HSB_SHARD_INDEX (from 0) and\n"
                     "HSB_SHARD_COUNT. An index list (--array=1,3,7) is refused: use a range (--array=A-B:S)");

  CLI::App* info = app.add_subcommand(
      "info",
      "Describe a data set (kind, bounds, cell types and counts, arrays, eigenvalue ranges) and print\n"
      "the scene with every automatic value resolved, as TOML to save and edit.");
  std::vector<std::string> info_inputs;
  std::string info_array;
  bool list_formats = false;
  info->add_option("inputs", info_inputs, "Scene files (.toml) or data files (" + hsb::readable_extensions_text() + ")");
  info->add_flag("--formats", list_formats,
                 "List the data formats hsb knows: those it reads, and those it names and says how to convert");
  info->add_option("--array", info_array, "Tensor array of a data file (default: its active tensors)");
  std::vector<std::string> info_overrides;
  info->add_option("--set", info_overrides, "Override a scene key, as for render (the values shown follow it)")
      ->allow_extra_args(false);
  info->footer(
      "Everything printed is TOML: the description as comments, then the scene with every automatic\n"
      "value written out (hsb info x.vtu > x.toml gives a scene to edit). A data file stands for the\n"
      "scene that names only it.");

  CLI::App* keys = app.add_subcommand(
      "keys", "List every scene key: its type, allowed values, default, unit and meaning (tab-separated).");
  keys->footer(
      "One line per key, in the order of scenes/README.md, which says more about each. \"D\" is the\n"
      "data's diagonal: lengths in the data's units must lie within the range printed for them.");

  CLI::App* exporter = app.add_subcommand(
      "export", "Write each scene's trajectories and sources as VTK PolyData (.vtp) for ParaView.");
  std::vector<std::string> export_scenes;
  std::string export_dir = "out";
  std::vector<std::string> export_overrides;
  std::string format = "vtp";
  exporter->add_option("scenes", export_scenes, "Scene files (.toml) or data files, as for render")->required();
  exporter->add_option("-o,--output", export_dir, "Folder for the files")->capture_default_str();
  exporter->add_option("--set", export_overrides, "Override a scene key, as for render")
      ->allow_extra_args(false);
  exporter->add_option("--format", format,
                       "vtp: trajectories and sources for ParaView; pov: the scene for POV-Ray 3.7 "
                       "(quartic kernel), with an .ini for `povray FILE.ini`")
      ->check(CLI::IsMember({"vtp", "pov"}))
      ->capture_default_str();
  exporter->footer(
      "vtp: writes <scene>_trajectories.vtp (polylines, arc length) and <scene>_sources.vtp (points\n"
      "with tensor, eigenvalues, radii, scalar, and active tensors \"glyph\" scaled so that\n"
      "ParaView's Tensor Glyph filter draws the same ellipsoids as an isolated source here).\n"
      "pov: writes <scene>.pov and <scene>.ini: the same sources as one POV-Ray blob, with the\n"
      "scene's camera, key light, shadows, background and image size.");

  int threads = 0;
  app.add_option("--threads", threads, "Use at most N threads (default: every core)")->check(CLI::PositiveNumber);
  app.add_option_function<std::string>(
         "--isa",
         [](const std::string& name) {
           try {
             hsb::force_isa(*hsb::parse_isa(name));
           } catch (const std::runtime_error& e) {
             throw CLI::ValidationError("--isa", e.what());
           }
         },
         "Trace with this instruction set (default: the processor's best; also HSB_ISA=NAME), to reproduce\n"
         "what another processor does; every one gives the same pictures, byte for byte")
      ->check(CLI::IsMember({"sse2", "sse4.2", "avx", "avx2", "avx512"}))
      ->trigger_on_parse();

  CLI11_PARSE(app, argc, argv);
  try {
    hsb::active_isa();  // a bad HSB_ISA is one error here, not one per scene
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "hsb: %s\n", hsb::shown(e.what()).c_str());
    return 2;
  }
  std::optional<tbb::global_control> thread_limit;

  if (threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  // Before any thread starts (TBB's, the image module's, the libraries'):
  // TBB kept to the room ulimit -u leaves, or one message where there is
  // no room for a run.
  try {
    hsb::fit_threads_to_room();
  } catch (const hsb::ResourceError& e) {
    std::fprintf(stderr, "hsb: %s\n", hsb::shown(e.what()).c_str());
    return 1;
  }

  // Runs `work` for inputs [0, count), named name_of(i); each failure is
  // reported once as it happens and again, with the others, in a summary
  // at the end.
  auto for_each = [](std::size_t count, auto&& name_of, const char* noun, auto&& work) {
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < count; ++i) {
      const std::string input = name_of(i);
      std::string message;
      try {
        work(i);
        continue;
      } catch (const hsb::SceneError& e) {
        message = e.what();
      } catch (const std::exception& e) {
        // Data errors already start with the data file's path; name the
        // input only when it adds something.
        message = e.what();
        if (message.rfind(input + ":", 0) != 0) message = input + ": " + message;
      }
      std::fprintf(stderr, "hsb: %s\n", hsb::shown(message).c_str());
      failures.push_back(message);
    }
    // One input's error needs no summary; a batch's failures are listed
    // again at its end, where a long log is read first.
    if (!failures.empty() && count > 1) {
      std::fprintf(stderr, "hsb: %zu of %zu %s failed:\n", failures.size(), count, noun);
      for (const std::string& f : failures) std::fprintf(stderr, "  %s\n", hsb::shown(f.substr(0, f.find('\n'))).c_str());
    }
    return failures.empty() ? 0 : 1;
  };

  // For info and export, what they print is what was asked for: a failed
  // write (a full disk under `> scene.toml`) fails the command.
  const auto printed = [&](int status) {
    std::string why;
    if (standard_output_written(why)) return status;
    std::fprintf(stderr, "hsb: cannot write to standard output: %s\n", why.c_str());
    return 1;
  };
  if (*keys) {
    std::printf("key\ttype\tvalues\tdefault\tunit\tmeaning\n");
    for (const hsb::KeySchema& k : hsb::scene_keys()) {
      const std::string fallback = k.default_kind == hsb::KeyDefault::value       ? k.fallback
                                   : k.default_kind == hsb::KeyDefault::automatic ? "automatic: " + k.rule
                                                                                  : k.rule;
      std::printf("%s\t%s\t%s\t%s\t%s\t%s\n", k.path.c_str(), hsb::type_text(k).c_str(), hsb::values_text(k).c_str(),
                  fallback.c_str(), k.unit.c_str(), k.doc.c_str());
    }
    return printed(0);
  }
  if (*info && list_formats) {
    std::printf("format\textensions\thsb reads it\n");
    for (const hsb::DataFormat& f : hsb::data_formats()) {
      std::string extensions;
      for (const std::string& e : f.extensions) extensions += (extensions.empty() ? "" : " ") + e;
      std::printf("%s\t%s\t%s\n", f.name.c_str(), extensions.c_str(), f.readable() ? "yes" : ("no: " + f.advice).c_str());
    }
    return printed(0);
  }
  if (*info && info_inputs.empty()) {
    std::fprintf(stderr, "hsb info: give scene or data files (or --formats)\n");
    return 106;
  }
  if (*info) {
    return printed(for_each(info_inputs.size(), [&](std::size_t i) { return info_inputs[i]; }, "inputs", [&](std::size_t i) {
      const std::string& input = info_inputs[i];
      std::vector<std::string> with_array = info_overrides;
      if (!info_array.empty()) with_array.push_back("data.array=" + info_array);
      hsb::SceneSpec spec = hsb::load_scene_or_data_file(input, with_array);
      std::istringstream description(hsb::describe_data(spec.pipeline.data));
      for (std::string line; std::getline(description, line);) std::printf("# %s\n", line.c_str());
      const hsb::ColorManagement color = scene_color_management(spec);
      const std::unique_ptr<hsb::PreparedScene> prepared = hsb::prepare_scene(std::move(spec), color);
      for (const std::string& warning : prepared->warnings) std::printf("# warning: %s\n", warning.c_str());
      std::fputs(hsb::pinned_scene_toml(*prepared).c_str(), stdout);
    }));
  }
  if (*exporter) {
    return printed(for_each(export_scenes.size(), [&](std::size_t i) { return export_scenes[i]; }, "scenes", [&](std::size_t i) {
      const hsb::ExportFormat f = format == "pov" ? hsb::ExportFormat::pov : hsb::ExportFormat::vtp;
      for (const std::string& path : hsb::run_export_job({export_scenes[i], export_overrides, export_dir, f}))
        std::printf("%s\n", path.c_str());
    }));
  }
  // A render writes images (or checks them with --skip-existing): the
  // image module loads while the first scene is read. A render that fails
  // before it needs the module does not wait for it: main() ends with
  // _exit, which runs none of the static destructors that must not meet
  // the libraries' constructors still running on the loader's thread
  // (a scene that failed at once crashed so, 1 in 150, when main returned
  // through exit). A scene with a bad key took half a second to say so.
  hsb::preload_image_io();
  // The batch: every scene times every swept value, this node's share,
  // each item made when its turn comes.
  hsb::Shard shard;
  std::optional<hsb::Batch> batch;
  try {
    if (shard_text == "auto") {
      // A log that says which share a task took is the one place a
      // scheduler's numbering that went wrong shows.
      const hsb::SchedulerShare share = hsb::scheduler_share_of_process();
      shard = share.shard;
      if (!quiet) std::fprintf(stderr, "hsb: %s\n", share.origin.c_str());
    } else if (!shard_text.empty()) {
      shard = hsb::parse_shard(shard_text);
    }
    batch.emplace(scenes, overrides, as_series);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "hsb: %s\n", hsb::shown(e.what()).c_str());
    return 2;
  }
  const auto item_at = [&](std::size_t j) { return batch->item(hsb::Batch::shard_position(shard, j)); };
  const auto name_of = [&](std::size_t j) {
    const hsb::BatchItem item = item_at(j);
    return item.variant.empty() ? item.scene : item.scene + " [" + item.variant + "]";
  };
  const std::size_t mine = batch->shard_size(shard);
  // More tasks than images leaves some shares empty: no failure, but a
  // log with nothing in it reads as one (even with --quiet).
  if (mine == 0) {
    std::fprintf(stderr, "hsb: share %d/%d of %zu %s holds none: nothing to render\n", shard.index, shard.count,
                 batch->size(), batch->size() == 1 ? "item" : "items");
    return 0;
  }
  hsb::BatchProgress progress(hsb::BatchProgress::mode_for(quiet), mine);
  std::size_t skipped = 0;
  std::map<std::string, std::string> written;  // image → the scene that wrote it
  std::map<std::string, std::vector<std::string>> series_settings;  // a series' shared settings, by its first step
  const auto series_progress = [&](hsb::SeriesWork work, double fraction) {
    progress.update(work == hsb::SeriesWork::reading ? hsb::JobStage::sharing : hsb::JobStage::waiting, fraction);
  };
  const int status = for_each(mine, name_of, "images", [&](std::size_t i) {
    const hsb::BatchItem item = item_at(i);
    if (!item.error.empty()) throw hsb::SceneError(item.error);
    progress.start(i, std::filesystem::path(item.scene).filename().string() +
                          (item.variant.empty() ? "" : " [" + item.variant + "]"));
    // A series' steps share one glyph scale, colour range, size and camera,
    // computed once per series (a batch may render its steps one after another),
    // and kept in the output folder for the other tasks of a job array.
    std::vector<std::string> job_overrides = item.overrides;
    if (!item.series.empty()) {
      std::string key = item.series.front().scene;
      for (const std::string& o : item.series.front().overrides) key += "\n" + o;
      auto found = series_settings.find(key);
      if (found == series_settings.end())
        found = series_settings.emplace(key, hsb::series_settings_in(output_dir, item.series, series_progress)).first;
      job_overrides.insert(job_overrides.end(), found->second.begin(), found->second.end());
    }
    hsb::RenderJob job{item.scene, job_overrides, output_dir, item.variant, skip_existing,
                       [&](hsb::JobStage stage, double fraction) { progress.update(stage, fraction); }, &written};
    hsb::RenderSummary summary;
    try {
      summary = hsb::run_render_job(job);
    } catch (const hsb::SceneError& e) {
      progress.finish();
      throw hsb::SceneError(hsb::located_error(item, e.what()));
    } catch (...) {
      progress.finish();
      throw;
    }
    progress.finish();
    if (summary.skipped) {
      ++skipped;
      if (!quiet) std::printf("%s  up to date, skipped\n", summary.image_path.c_str());
      std::fflush(stdout);
    } else if (!quiet) {
      print_summary(summary, stats);
    } else {
      for (const std::string& w : summary.warnings) std::fprintf(stderr, "hsb: warning: %s\n", hsb::shown(w).c_str());
    }
  });
  if (skipped && !quiet) std::printf("%zu of %zu images up to date, skipped\n", skipped, mine);
  // The images are the product; the lines printed are a report, so a
  // closed pipe (`| head`) is no failure, only said.
  std::string why;
  if (!standard_output_written(why) && why != std::strerror(EPIPE))
    std::fprintf(stderr, "hsb: warning: the report did not reach standard output (%s); the images are written\n",
                 why.c_str());
  return status;
}

}  // namespace

// The process ends without its libraries' static destructors and exit
// handlers: with the image module loaded, 380 libraries (VTK, PROJ, GDAL,
// OpenSSL among them) would tear their state down, paging back in data
// nobody touched, 8–9 ms of every run on fig09 after the picture was
// written. Nothing of hsb's waits on them: run() has closed its files and
// judged its reports' writing (a closed pipe is no failure), and what is
// still buffered for standard output and error is flushed here.
int main(int argc, char** argv) {
  const int status = run(argc, argv);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  _exit(status);
}
