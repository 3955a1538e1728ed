#pragma once
// A time series' shared settings (renderer/app/series_scale.h) kept in
// the output folder, so that the tasks of a job array find them once
// between them. Each task used to read every step before its share: a
// 5,000-step series cost every one of 50 tasks the same half hour, and
// a resubmitted task paid it again.
//
// The file is `.hsb-series-SHA1.toml` in the output folder, SHA1 naming
// what the settings come from: hsb's version and each step's scene hash
// (its text, --set values, data files' contents and colour
// configuration, as an image's hsb:scene_sha1). Changed data, scene or
// hsb name another file, so one found is never stale. While one task
// reads the steps, the others wait on `.hsb-series-SHA1.lock` (flock;
// released by the kernel if the task dies) and then read its file. Where
// the folder takes no lock or no file (NFS without locks, read-only), each
// task reads the steps itself, as before: the settings are the same.
//
// A file found is used only when this user owns it, it is a regular
// file of at most 64 KB, it names the same SHA1, and every line sets one
// of the keys a series pins; otherwise it is read again and replaced.

#include <functional>
#include <string>
#include <vector>

#include "renderer/app/series_scale.h"

namespace hsb {

enum class SeriesWork {
  reading,  // this task reads the steps (fraction: of the steps read)
  waiting   // another task does (fraction 0)
};

// shared_series_settings(members), from `folder`'s file when there is a
// good one, else computed and stored there.
std::vector<std::string> series_settings_in(const std::string& folder, const std::vector<SeriesMember>& members,
                                            const std::function<void(SeriesWork, double)>& progress = {});

}  // namespace hsb
