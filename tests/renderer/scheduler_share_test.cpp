// --shard auto: every array of every scheduler, range by range, gives its
// tasks shares that hold each item of a batch exactly once (no image lost,
// none rendered twice); what cannot be shared out so (an index list,
// variables that disagree or are not numbers) is refused, naming the
// variable and its value, never half rendered.

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "renderer/app/batch.h"
#include "renderer/app/scheduler_share.h"

namespace hsb {
namespace {

using Environment = std::map<std::string, std::string>;

template <class Number>
std::string text(Number n) {
  return std::to_string(n);
}

// Batches of 0 to 40 items (scenes that do not exist are one item each).
const std::vector<Batch>& batches_of_every_size() {
  static const std::vector<Batch> batches = [] {
    std::vector<Batch> made;
    std::vector<std::string> scenes;
    for (int n = 0; n <= 40; ++n) {
      made.emplace_back(scenes, std::vector<std::string>{});
      scenes.push_back("no_such_folder/item" + text(n) + ".toml");
    }
    return made;
  }();
  return batches;
}

// Whether the shares of an array's tasks are 1/N … N/N, one each, and so
// hold every item of every batch exactly once.
::testing::AssertionResult each_item_once(const std::vector<Shard>& shares) {
  std::set<int> indices;
  for (const Shard& s : shares) {
    if (s.count != int(shares.size()) || s.index < 1 || s.index > s.count || !indices.insert(s.index).second)
      return ::testing::AssertionFailure()
             << "share " << s.index << "/" << s.count << " among " << shares.size() << " tasks";
  }
  for (const Batch& batch : batches_of_every_size()) {
    std::vector<int> held(batch.size(), 0);
    for (const Shard& s : shares)
      for (std::size_t j = 0; j < batch.shard_size(s); ++j) {
        const std::size_t i = Batch::shard_position(s, j);
        if (i >= batch.size())
          return ::testing::AssertionFailure()
                 << "share " << s.index << "/" << s.count << " holds item " << i << " of " << batch.size();
        ++held[i];
      }
    for (std::size_t i = 0; i < held.size(); ++i)
      if (held[i] != 1)
        return ::testing::AssertionFailure()
               << "item " << i << " of " << batch.size() << " held " << held[i] << " times";
  }
  return ::testing::AssertionSuccess();
}

// The shares of an array's tasks, each task's environment given; a task
// refused fails the test.
std::vector<Shard> shares_of(const std::vector<Environment>& tasks, const std::string& array) {
  std::vector<Shard> shares;
  for (const Environment& task : tasks) {
    try {
      shares.push_back(scheduler_share(task).shard);
    } catch (const std::invalid_argument& e) {
      ADD_FAILURE() << array << ": a task refused: " << e.what();
    }
  }
  return shares;
}

// What scheduler_share says to `environment`: its refusal, or "" when it
// gives a share.
std::string refusal(const Environment& environment) {
  try {
    scheduler_share(environment);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

#define EXPECT_REFUSED_SAYING(environment, words)                                                    \
  do {                                                                                               \
    const std::string said = refusal(environment);                                                   \
    EXPECT_EQ(said.rfind("--shard auto: ", 0), 0u) << "not refused as expected: \"" << said << "\""; \
    EXPECT_NE(said.find(words), std::string::npos) << said;                                          \
  } while (0)

// The tasks of Slurm's --array=first-given_last:step, with MAX as Slurm
// may set it: the range's last index, or the one given.
std::vector<Environment> slurm_array(long long first, long long given_last, long long step, bool max_given,
                                     bool with_step) {
  std::vector<long long> ids;
  for (long long id = first; id <= given_last; id += step) ids.push_back(id);
  std::vector<Environment> tasks;
  for (long long id : ids) {
    Environment e{{"SLURM_JOB_ID", "1234"},
                  {"SLURM_ARRAY_JOB_ID", "1230"},
                  {"SLURM_ARRAY_TASK_ID", text(id)},
                  {"SLURM_ARRAY_TASK_MIN", text(first)},
                  {"SLURM_ARRAY_TASK_MAX", text(max_given ? given_last : ids.back())},
                  {"SLURM_ARRAY_TASK_COUNT", text(ids.size())}};
    if (with_step) e["SLURM_ARRAY_TASK_STEP"] = text(step);
    tasks.push_back(e);
  }
  return tasks;
}

TEST(SchedulerShare, EverySlurmRangeSharesOutEveryItemOnce) {
  for (long long a = 0; a <= 20; ++a)
    for (long long b = a; b <= 20; ++b)
      for (long long s = 1; s <= 5; ++s)
        for (bool max_given : {false, true})
          for (bool with_step : {true, false}) {
            if (!with_step && s != 1) continue;  // Slurm says a step other than 1
            const std::string array = "--array=" + text(a) + "-" + text(b) + ":" + text(s) +
                                      (max_given ? " (MAX as given)" : "") + (with_step ? "" : " (no STEP)");
            const std::vector<Shard> shares = shares_of(slurm_array(a, b, s, max_given, with_step), array);
            ASSERT_TRUE(each_item_once(shares)) << array;
          }
}

// The arrays: 0-6:2 gave "5/4" and "7/4"; 1,3,7 lost 7 of 22 images.
TEST(SchedulerShare, SlurmStepsAreFollowedAndIndexListsRefused) {
  const std::vector<Environment> stepped = slurm_array(0, 6, 2, false, true);
  EXPECT_EQ(scheduler_share(stepped[2]).origin, "Slurm array task 4 of 0-6:2: share 3/4");
  EXPECT_EQ(scheduler_share(stepped[3]).origin, "Slurm array task 6 of 0-6:2: share 4/4");
  for (bool with_step : {false, true})
    for (const char* id : {"1", "3", "7"}) {
      Environment task{{"SLURM_ARRAY_TASK_ID", id},
                       {"SLURM_ARRAY_TASK_MIN", "1"},
                       {"SLURM_ARRAY_TASK_MAX", "7"},
                       {"SLURM_ARRAY_TASK_COUNT", "3"}};
      if (with_step) task["SLURM_ARRAY_TASK_STEP"] = "1";
      EXPECT_REFUSED_SAYING(task,
                            "an index list: use a range with a step (--array=A-B:S) or set HSB_SHARD_INDEX "
                            "and HSB_SHARD_COUNT");
      EXPECT_REFUSED_SAYING(task, "SLURM_ARRAY_TASK_COUNT=3");
    }
  // Every list of indices 0-9: an irregular one is refused by every task
  // (never some tasks rendering while the others fail); a regular one,
  // told its step, is a range.
  for (unsigned members = 0; members < 1024; ++members) {
    std::vector<long long> ids;
    for (long long i = 0; i < 10; ++i)
      if (members & (1u << i)) ids.push_back(i);
    if (ids.size() < 2) continue;
    long long stride = 0;  // the greatest common divisor of the gaps
    for (std::size_t i = 1; i < ids.size(); ++i) stride = std::gcd(stride, ids[i] - ids[i - 1]);
    const bool regular = (ids.back() - ids.front()) / stride + 1 == static_cast<long long>(ids.size());
    std::string list;
    for (long long id : ids) list += (list.empty() ? "" : ",") + text(id);
    for (const std::optional<long long> step :
         {std::optional<long long>(), std::optional<long long>(1), std::optional<long long>(stride)}) {
      std::vector<Environment> tasks;
      for (long long id : ids) {
        Environment e{{"SLURM_ARRAY_TASK_ID", text(id)},
                      {"SLURM_ARRAY_TASK_MIN", text(ids.front())},
                      {"SLURM_ARRAY_TASK_MAX", text(ids.back())},
                      {"SLURM_ARRAY_TASK_COUNT", text(ids.size())}};
        if (step) e["SLURM_ARRAY_TASK_STEP"] = text(*step);
        tasks.push_back(e);
      }
      const bool a_range = regular && (stride == 1 || step == stride);
      const std::string array = "--array=" + list + " with STEP " + (step ? text(*step) : "unset");
      if (a_range) {
        EXPECT_TRUE(each_item_once(shares_of(tasks, array))) << array;
      } else {
        for (const Environment& task : tasks) EXPECT_REFUSED_SAYING(task, "SLURM_ARRAY_TASK_");
      }
    }
  }
}

TEST(SchedulerShare, EveryGridEngineRangeSharesOutEveryItemOnce) {
  for (long long a = 1; a <= 20; ++a)
    for (long long b = a; b <= 20; ++b)
      for (long long s = 1; s <= 5; ++s)
        for (bool last_given : {true, false}) {
          std::vector<long long> ids;
          for (long long id = a; id <= b; id += s) ids.push_back(id);
          std::vector<Environment> tasks;
          for (long long id : ids)
            tasks.push_back({{"JOB_ID", "77"},
                             {"SGE_TASK_ID", text(id)},
                             {"SGE_TASK_FIRST", text(a)},
                             {"SGE_TASK_LAST", text(last_given ? b : ids.back())},
                             {"SGE_TASK_STEPSIZE", text(s)}});
          const std::string array = "qsub -t " + text(a) + "-" + text(b) + ":" + text(s);
          ASSERT_TRUE(each_item_once(shares_of(tasks, array))) << array;
        }
  EXPECT_EQ(scheduler_share(
                {{"SGE_TASK_ID", "5"}, {"SGE_TASK_FIRST", "1"}, {"SGE_TASK_LAST", "16"}, {"SGE_TASK_STEPSIZE", "2"}})
                .origin,
            "Grid Engine array task 5 of 1-15:2: share 3/8");
}

TEST(SchedulerShare, EveryLsfRangeSharesOutEveryItemOnce) {
  // "hsb[first-last:step]": the count from LSB_JOBINDEX_END, HSB_SHARD_COUNT or both.
  for (long long a = 1; a <= 12; ++a)
    for (long long b = a; b <= 20; ++b)
      for (long long s = 1; s <= 4; ++s)
        for (int counted = 0; counted < 3; ++counted) {
          std::vector<long long> ids;
          for (long long id = a; id <= b; id += s) ids.push_back(id);
          std::vector<Environment> tasks;
          for (long long id : ids) {
            Environment e{{"LSB_JOBID", "55"}, {"LSB_JOBINDEX", text(id)}};
            if (a != 1) e["HSB_SHARD_FIRST"] = text(a);
            if (s != 1) e["LSB_JOBINDEX_STEP"] = text(s);
            if (counted != 1) e["LSB_JOBINDEX_END"] = text(b);
            if (counted != 0) e["HSB_SHARD_COUNT"] = text(ids.size());
            tasks.push_back(e);
          }
          const std::string array =
              "bsub -J \"hsb[" + text(a) + "-" + text(b) + ":" + text(s) + "]\" (" + text(counted) + ")";
          ASSERT_TRUE(each_item_once(shares_of(tasks, array))) << array;
        }
  EXPECT_EQ(scheduler_share({{"LSB_JOBINDEX", "4"}, {"LSB_JOBINDEX_END", "16"}}).origin,
            "LSF array index 4 of 1-16: share 4/16");
  // A list looks like a range up to its greatest index; HSB_SHARD_COUNT
  // tells it is not one.
  for (const char* index : {"1", "3", "7"})
    EXPECT_REFUSED_SAYING((Environment{{"LSB_JOBINDEX", index}, {"LSB_JOBINDEX_END", "7"}, {"HSB_SHARD_COUNT", "3"}}),
                          "HSB_SHARD_COUNT=3 disagrees with LSB_JOBINDEX_END=7");
  EXPECT_REFUSED_SAYING((Environment{{"LSB_JOBINDEX", "2"}}), "HSB_SHARD_COUNT");
}

TEST(SchedulerShare, EveryPbsAndTorqueRangeSharesOutEveryItemOnce) {
  for (const char* variable : {"PBS_ARRAY_INDEX", "PBS_ARRAYID"})
    for (long long first = 0; first <= 5; ++first)
      for (long long step = 1; step <= 3; ++step)
        for (long long count = 1; count <= 20; ++count) {
          std::vector<Environment> tasks;
          for (long long k = 0; k < count; ++k) {
            Environment e{{"PBS_JOBID", "9[" + text(first + k * step) + "].server"},
                          {variable, text(first + k * step)},
                          {"HSB_SHARD_COUNT", text(count)}};
            if (first != 0) e["HSB_SHARD_FIRST"] = text(first);  // else the default
            if (step != 1) e["HSB_SHARD_STEP"] = text(step);
            tasks.push_back(e);
          }
          const std::string array = std::string(variable) + " " + text(first) + ", +" + text(step) + ", " + text(count);
          ASSERT_TRUE(each_item_once(shares_of(tasks, array))) << array;
        }
  EXPECT_EQ(scheduler_share({{"PBS_ARRAY_INDEX", "5"}, {"HSB_SHARD_FIRST", "1"}, {"HSB_SHARD_COUNT", "16"}}).origin,
            "PBS Pro array index 5 of 1-16: share 5/16");
  // qsub -J 1-16 with HSB_SHARD_FIRST left at 0: the last task says so.
  EXPECT_REFUSED_SAYING((Environment{{"PBS_ARRAY_INDEX", "16"}, {"HSB_SHARD_COUNT", "16"}}), "PBS_ARRAY_INDEX=16");
  EXPECT_REFUSED_SAYING((Environment{{"PBS_ARRAY_INDEX", "16"}, {"HSB_SHARD_COUNT", "16"}}), "HSB_SHARD_FIRST");
  EXPECT_REFUSED_SAYING((Environment{{"PBS_ARRAY_INDEX", "3"}}), "HSB_SHARD_COUNT is not set");
  EXPECT_REFUSED_SAYING((Environment{{"PBS_ARRAYID", "3"}}), "HSB_SHARD_COUNT is not set");
}

TEST(SchedulerShare, EveryZeroBasedArraySharesOutEveryItemOnce) {
  for (long long count = 1; count <= 20; ++count) {
    std::vector<Environment> kubernetes, aws_sized, aws_counted, aws_both, explicit_index;
    for (long long i = 0; i < count; ++i) {
      kubernetes.push_back({{"JOB_COMPLETION_INDEX", text(i)}, {"HSB_SHARD_COUNT", text(count)}});
      aws_sized.push_back({{"AWS_BATCH_JOB_ID", "x:" + text(i)},
                           {"AWS_BATCH_JOB_ARRAY_INDEX", text(i)},
                           {"AWS_BATCH_JOB_ARRAY_SIZE", text(count)}});
      aws_counted.push_back({{"AWS_BATCH_JOB_ARRAY_INDEX", text(i)}, {"HSB_SHARD_COUNT", text(count)}});
      aws_both.push_back({{"AWS_BATCH_JOB_ARRAY_INDEX", text(i)},
                          {"AWS_BATCH_JOB_ARRAY_SIZE", text(count)},
                          {"HSB_SHARD_COUNT", text(count)}});
      // HTCondor's $(Process), overriding a Slurm index list around it.
      explicit_index.push_back({{"HSB_SHARD_INDEX", text(i)},
                                {"HSB_SHARD_COUNT", text(count)},
                                {"SLURM_ARRAY_TASK_ID", "7"},
                                {"SLURM_ARRAY_TASK_MIN", "1"},
                                {"SLURM_ARRAY_TASK_MAX", "7"},
                                {"SLURM_ARRAY_TASK_COUNT", "3"}});
    }
    EXPECT_TRUE(each_item_once(shares_of(kubernetes, "Kubernetes"))) << count;
    EXPECT_TRUE(each_item_once(shares_of(aws_sized, "AWS Batch, its size"))) << count;
    EXPECT_TRUE(each_item_once(shares_of(aws_counted, "AWS Batch, HSB_SHARD_COUNT"))) << count;
    EXPECT_TRUE(each_item_once(shares_of(aws_both, "AWS Batch, both"))) << count;
    EXPECT_TRUE(each_item_once(shares_of(explicit_index, "HSB_SHARD_INDEX"))) << count;
  }
  EXPECT_EQ(scheduler_share({{"JOB_COMPLETION_INDEX", "3"}, {"HSB_SHARD_COUNT", "16"}}).origin,
            "Kubernetes completion index 3 of 0-15: share 4/16");
  EXPECT_EQ(scheduler_share({{"HSB_SHARD_INDEX", "0"}, {"HSB_SHARD_COUNT", "1"}}).origin,
            "HSB_SHARD_INDEX 0 of 0-0: share 1/1");
  // What it overrides is said, in case the submitting shell exported it to every task.
  EXPECT_EQ(scheduler_share({{"HSB_SHARD_INDEX", "2"}, {"HSB_SHARD_COUNT", "4"}, {"PBS_ARRAYID", "7"}}).origin,
            "HSB_SHARD_INDEX 2 of 0-3: share 3/4 (over PBS_ARRAYID=7)");
  EXPECT_REFUSED_SAYING((Environment{{"JOB_COMPLETION_INDEX", "3"}}), "HSB_SHARD_COUNT is not set");
  EXPECT_REFUSED_SAYING((Environment{{"AWS_BATCH_JOB_ARRAY_INDEX", "3"}}), "HSB_SHARD_COUNT is not set");
  EXPECT_REFUSED_SAYING((Environment{{"HSB_SHARD_INDEX", "3"}}), "HSB_SHARD_COUNT is not set");
  EXPECT_REFUSED_SAYING(
      (Environment{{"AWS_BATCH_JOB_ARRAY_INDEX", "3"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "8"}, {"HSB_SHARD_COUNT", "9"}}),
      "HSB_SHARD_COUNT=9 disagrees with AWS_BATCH_JOB_ARRAY_SIZE=8");
}

TEST(SchedulerShare, BadValuesAreRefusedNamingTheVariableAndItsValue) {
  const Environment slurm{{"SLURM_ARRAY_TASK_ID", "4"},
                          {"SLURM_ARRAY_TASK_MIN", "0"},
                          {"SLURM_ARRAY_TASK_MAX", "6"},
                          {"SLURM_ARRAY_TASK_STEP", "2"},
                          {"SLURM_ARRAY_TASK_COUNT", "4"}};
  const Environment grid_engine{
      {"SGE_TASK_ID", "4"}, {"SGE_TASK_FIRST", "1"}, {"SGE_TASK_LAST", "16"}, {"SGE_TASK_STEPSIZE", "1"}};
  const Environment lsf{{"LSB_JOBINDEX", "4"},     {"LSB_JOBINDEX_END", "16"}, {"LSB_JOBINDEX_STEP", "1"},
                        {"HSB_SHARD_COUNT", "16"}, {"HSB_SHARD_FIRST", "1"},   {"HSB_SHARD_STEP", "1"}};
  const Environment pbs{
      {"PBS_ARRAY_INDEX", "4"}, {"HSB_SHARD_COUNT", "16"}, {"HSB_SHARD_FIRST", "1"}, {"HSB_SHARD_STEP", "1"}};
  const Environment torque{{"PBS_ARRAYID", "4"}, {"HSB_SHARD_COUNT", "16"}};
  const Environment kubernetes{{"JOB_COMPLETION_INDEX", "4"}, {"HSB_SHARD_COUNT", "16"}};
  const Environment aws{{"AWS_BATCH_JOB_ARRAY_INDEX", "4"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "16"}};
  const Environment explicit_share{{"HSB_SHARD_INDEX", "4"}, {"HSB_SHARD_COUNT", "16"}};
  for (const Environment& good : {slurm, grid_engine, lsf, pbs, torque, kubernetes, aws, explicit_share}) {
    EXPECT_EQ(refusal(good), "");
    for (const auto& [variable, value] : good)
      for (const char* bad : {"", "abc", "-1", "1.5", " 4", "4 ", "+4", "4x", "0x10", "99999999999", "undefined"}) {
        // SGE_TASK_ID=undefined is Grid Engine's own word for "not an array".
        if (variable == "SGE_TASK_ID" && std::string(bad) == "undefined") continue;
        Environment e = good;
        e[variable] = bad;
        EXPECT_REFUSED_SAYING(e, variable + "=\"" + bad + "\"");
      }
  }
  // Zero where the least is 1.
  for (const char* variable : {"SLURM_ARRAY_TASK_STEP", "SLURM_ARRAY_TASK_COUNT"}) {
    Environment e = slurm;
    e[variable] = "0";
    EXPECT_REFUSED_SAYING(e, std::string(variable) + "=\"0\"");
  }
  // An ID outside the range, or off its step.
  for (const char* id : {"8", "9", "3", "100"}) {
    Environment e = slurm;
    e["SLURM_ARRAY_TASK_ID"] = id;
    EXPECT_REFUSED_SAYING(e, std::string("SLURM_ARRAY_TASK_ID=") + id);
  }
  for (const char* index : {"16", "17"}) {
    Environment e = kubernetes;
    e["JOB_COMPLETION_INDEX"] = index;
    EXPECT_REFUSED_SAYING(e, std::string("JOB_COMPLETION_INDEX=") + index);
  }
  // A count that disagrees with the range.
  for (const char* count : {"3", "5", "1"}) {
    Environment e = slurm;
    e["SLURM_ARRAY_TASK_COUNT"] = count;
    EXPECT_REFUSED_SAYING(e, std::string("SLURM_ARRAY_TASK_COUNT=") + count);
  }
  Environment reversed = slurm;
  reversed["SLURM_ARRAY_TASK_MIN"] = "7";
  EXPECT_REFUSED_SAYING(reversed, "SLURM_ARRAY_TASK_MAX=6 is below SLURM_ARRAY_TASK_MIN=7");
  for (const char* missing : {"SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_MAX", "SLURM_ARRAY_TASK_COUNT"}) {
    Environment e = slurm;
    e.erase(missing);
    EXPECT_REFUSED_SAYING(e, std::string(missing) + " is not set");
  }
  Environment lsf_step = lsf;
  lsf_step["HSB_SHARD_STEP"] = "2";
  EXPECT_REFUSED_SAYING(lsf_step, "HSB_SHARD_STEP=2 disagrees with LSB_JOBINDEX_STEP=1");
}

TEST(SchedulerShare, WithoutAnArrayTaskItSaysWhatItLookedFor) {
  const std::string none = refusal({{"HOME", "/home/x"}, {"HSB_SHARD_COUNT", "4"}});
  for (const char* variable : {"HSB_SHARD_INDEX", "SLURM_ARRAY_TASK_ID", "SGE_TASK_ID", "LSB_JOBINDEX",
                               "PBS_ARRAY_INDEX", "PBS_ARRAYID", "JOB_COMPLETION_INDEX", "AWS_BATCH_JOB_ARRAY_INDEX"})
    EXPECT_NE(none.find(variable), std::string::npos) << none;
  EXPECT_NE(none.find("--shard K/N"), std::string::npos) << none;
  // Jobs that are not arrays say so.
  EXPECT_REFUSED_SAYING((Environment{{"SLURM_JOB_ID", "12"}}), "a Slurm job that is not an array");
  EXPECT_REFUSED_SAYING((Environment{{"LSB_JOBID", "12"}, {"LSB_JOBINDEX", "0"}}), "LSB_JOBINDEX=0");
  EXPECT_REFUSED_SAYING((Environment{{"SGE_TASK_ID", "undefined"}, {"SGE_TASK_FIRST", "undefined"}}),
                        "SGE_TASK_ID=undefined");
  EXPECT_REFUSED_SAYING((Environment{{"PBS_JOBID", "12.server"}}), "not an array");
  // Two schedulers' arrays at once: neither is taken.
  EXPECT_REFUSED_SAYING((Environment{{"SLURM_ARRAY_TASK_ID", "1"},
                                     {"SLURM_ARRAY_TASK_MIN", "0"},
                                     {"SLURM_ARRAY_TASK_MAX", "3"},
                                     {"SLURM_ARRAY_TASK_COUNT", "4"},
                                     {"JOB_COMPLETION_INDEX", "1"},
                                     {"HSB_SHARD_COUNT", "4"}}),
                        "are both set");
}

TEST(SchedulerShare, ReadsTheProcessEnvironment) {
  // HSB_SHARD_INDEX overrides whatever scheduler runs the test; the
  // variables are put back as they were.
  std::map<std::string, std::optional<std::string>> before;
  for (const char* name : {"HSB_SHARD_INDEX", "HSB_SHARD_COUNT"})
    if (const char* value = std::getenv(name))
      before[name] = value;
    else
      before[name] = std::nullopt;
  setenv("HSB_SHARD_INDEX", "2", 1);
  setenv("HSB_SHARD_COUNT", "5", 1);
  const SchedulerShare share = scheduler_share_of_process();
  for (const auto& [name, value] : before) {
    if (value)
      setenv(name.c_str(), value->c_str(), 1);
    else
      unsetenv(name.c_str());
  }
  EXPECT_EQ(share.shard.index, 3);
  EXPECT_EQ(share.shard.count, 5);
}

}  // namespace
}  // namespace hsb
