#include "renderer/app/scheduler_share.h"

#include <unistd.h>  // environ

#include <climits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace hsb {
namespace {

using Environment = std::map<std::string, std::string>;

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("--shard auto: " + why); }

// The way out of every array hsb cannot follow.
const std::string use_explicit = "set HSB_SHARD_INDEX (from 0) and HSB_SHARD_COUNT instead";
// Slurm's index lists are the array most often given that hsb cannot follow.
const std::string list_advice =
    "an index list: use a range with a step (--array=A-B:S) or set HSB_SHARD_INDEX and HSB_SHARD_COUNT";

std::string text(long long n) { return std::to_string(n); }

const std::string* find(const Environment& environment, const std::string& name) {
  const auto found = environment.find(name);
  return found == environment.end() ? nullptr : &found->second;
}

// `value`, of variable `name`, as a whole number from `minimum` up. Digits
// only: a sign, a space or a fraction is a mistake to report, not a
// number to round. At most INT_MAX, since shares count in int (and
// ranges of such numbers stay far inside long long).
long long whole_number(const std::string& name, const std::string& value, long long minimum) {
  long long n = 0;
  bool ok = !value.empty();
  for (std::size_t i = 0; ok && i < value.size(); ++i) {
    ok = value[i] >= '0' && value[i] <= '9';
    n = n * 10 + (value[i] - '0');
    ok = ok && n <= INT_MAX;
  }
  if (!ok || n < minimum)
    refuse(name + "=\"" + value + "\" is not a whole number from " + text(minimum) + " to " + text(INT_MAX));
  return n;
}

std::optional<long long> optional_number(const Environment& environment, const std::string& name, long long minimum) {
  const std::string* value = find(environment, name);
  if (!value) return std::nullopt;
  return whole_number(name, *value, minimum);
}

long long required_number(const Environment& environment, const std::string& name, long long minimum,
                          const std::string& why) {
  const std::optional<long long> n = optional_number(environment, name, minimum);
  if (!n) refuse(name + " is not set: " + why);
  return *n;
}

// An array's indices: first, first + step, …, first + (count − 1)·step.
struct IndexRange {
  long long first = 0, step = 1, count = 1;
};

// As the schedulers write a range: "0-6:2", "1-16", "3-3".
std::string range_text(const IndexRange& range) {
  return text(range.first) + "-" + text(range.first + (range.count - 1) * range.step) +
         (range.step == 1 || range.count == 1 ? "" : ":" + text(range.step));
}

// The share of the task `task` ("Slurm array task 4") whose index, the
// value of `variable`, is `index`: K of count for the K-th index of
// `range`, which the variables `described_by` gave. An index that is not
// one of the range's means those variables do not describe the array:
// `advice` says what to do.
SchedulerShare share_of_task(const std::string& task, const std::string& variable, long long index,
                             const IndexRange& range, const std::string& described_by, const std::string& advice) {
  const long long offset = index - range.first;
  if (offset < 0 || offset % range.step != 0 || offset / range.step >= range.count)
    refuse(variable + "=" + text(index) + " is not one of the indices " + range_text(range) + " (from " + described_by +
           "): " + advice);
  const Shard shard{int(offset / range.step + 1), int(range.count)};
  return {shard, task + " of " + range_text(range) + ": share " + text(shard.index) + "/" + text(shard.count)};
}

// HSB_SHARD_INDEX from 0 and HSB_SHARD_COUNT: any scheduler (HTCondor's
// $(Process)), and the way out of every case below.
SchedulerShare explicit_share(const Environment& environment) {
  const long long index = required_number(environment, "HSB_SHARD_INDEX", 0, "");
  const long long count =
      required_number(environment, "HSB_SHARD_COUNT", 1, "HSB_SHARD_INDEX needs it: the number of tasks");
  return share_of_task("HSB_SHARD_INDEX " + text(index), "HSB_SHARD_INDEX", index, {0, 1, count}, "HSB_SHARD_COUNT",
                       "HSB_SHARD_INDEX counts from 0 to HSB_SHARD_COUNT - 1");
}

// Slurm gives the whole range, but of an index list (--array=1,3,7) only
// its least and greatest index and its size: a list is told from a range
// by its count, and refused.
SchedulerShare slurm_share(const Environment& environment) {
  const long long id = required_number(environment, "SLURM_ARRAY_TASK_ID", 0, "");
  const std::string why = "a task's rank in its array needs SLURM_ARRAY_TASK_MIN, _MAX and _COUNT; or " + use_explicit;
  const long long min = required_number(environment, "SLURM_ARRAY_TASK_MIN", 0, why);
  const long long max = required_number(environment, "SLURM_ARRAY_TASK_MAX", 0, why);
  const long long step = optional_number(environment, "SLURM_ARRAY_TASK_STEP", 1).value_or(1);
  const long long count = required_number(environment, "SLURM_ARRAY_TASK_COUNT", 1, why);
  if (max < min) refuse("SLURM_ARRAY_TASK_MAX=" + text(max) + " is below SLURM_ARRAY_TASK_MIN=" + text(min));
  // Rounded down: a range's greatest index need not lie on its step.
  const IndexRange range{min, step, (max - min) / step + 1};
  if (count != range.count)
    refuse("SLURM_ARRAY_TASK_COUNT=" + text(count) + " tasks between SLURM_ARRAY_TASK_MIN=" + text(min) +
           " and SLURM_ARRAY_TASK_MAX=" + text(max) + " are not the range " + range_text(range) + " (" +
           text(range.count) + " tasks) but " + list_advice);
  return share_of_task("Slurm array task " + text(id), "SLURM_ARRAY_TASK_ID", id, range,
                       "SLURM_ARRAY_TASK_MIN, _MAX and _STEP",
                       "is the array an index list? Use a range with a step (--array=A-B:S) or set HSB_SHARD_INDEX "
                       "and HSB_SHARD_COUNT");
}

// Grid Engine (SGE, Univa, Altair) arrays are ranges only (qsub -t A-B:S).
SchedulerShare grid_engine_share(const Environment& environment) {
  const long long id = required_number(environment, "SGE_TASK_ID", 1, "");
  const std::string why = "Grid Engine sets it for every array task (qsub -t A-B:S); or " + use_explicit;
  const long long first = required_number(environment, "SGE_TASK_FIRST", 1, why);
  const long long last = required_number(environment, "SGE_TASK_LAST", 1, why);
  const long long step = optional_number(environment, "SGE_TASK_STEPSIZE", 1).value_or(1);
  if (last < first) refuse("SGE_TASK_LAST=" + text(last) + " is below SGE_TASK_FIRST=" + text(first));
  return share_of_task("Grid Engine array task " + text(id), "SGE_TASK_ID", id,
                       {first, step, (last - first) / step + 1}, "SGE_TASK_FIRST, SGE_TASK_LAST and SGE_TASK_STEPSIZE",
                       use_explicit);
}

// LSF gives its array's step and greatest index but not where it starts
// (1 unless the -J says otherwise: HSB_SHARD_FIRST), nor its size, so an
// index list ("hsb[1,3,7]") looks like a range up to its greatest index:
// HSB_SHARD_COUNT, when given too, must agree, which catches it.
SchedulerShare lsf_share(const Environment& environment) {
  const long long index = required_number(environment, "LSB_JOBINDEX", 1, "");
  const std::optional<long long> given_first = optional_number(environment, "HSB_SHARD_FIRST", 1);
  const long long first = given_first.value_or(1);
  const std::string first_text =
      "the first index " + text(first) + (given_first ? " (HSB_SHARD_FIRST)" : " (HSB_SHARD_FIRST unset)");
  // A job with no step may carry LSB_JOBINDEX_STEP=0.
  const long long own_step = optional_number(environment, "LSB_JOBINDEX_STEP", 0).value_or(0);
  const std::optional<long long> given_step = optional_number(environment, "HSB_SHARD_STEP", 1);
  if (own_step > 0 && given_step && *given_step != own_step)
    refuse("HSB_SHARD_STEP=" + text(*given_step) + " disagrees with LSB_JOBINDEX_STEP=" + text(own_step));
  const long long step = own_step > 0 ? own_step : given_step.value_or(1);
  const std::optional<long long> end = optional_number(environment, "LSB_JOBINDEX_END", 1);
  const std::optional<long long> given_count = optional_number(environment, "HSB_SHARD_COUNT", 1);
  if (!end && !given_count)
    refuse("HSB_SHARD_COUNT is not set, nor LSB_JOBINDEX_END: set HSB_SHARD_COUNT to the number of array tasks");
  long long count = given_count.value_or(0);
  if (end) {
    if (*end < first) refuse("LSB_JOBINDEX_END=" + text(*end) + " is below " + first_text);
    const long long end_count = (*end - first) / step + 1;
    if (given_count && end_count != *given_count)
      refuse("HSB_SHARD_COUNT=" + text(*given_count) + " disagrees with LSB_JOBINDEX_END=" + text(*end) + ": from " +
             first_text + " in steps of " + text(step) + " the array holds " + text(end_count) +
             " indices: set HSB_SHARD_COUNT to the array's size (a -J other than the script's?); for an index list "
             "(\"hsb[1,3,7]\") " +
             use_explicit);
    count = end_count;
  }
  return share_of_task("LSF array index " + text(index), "LSB_JOBINDEX", index, {first, step, count},
                       "HSB_SHARD_FIRST (default 1), LSB_JOBINDEX_STEP and LSB_JOBINDEX_END or HSB_SHARD_COUNT",
                       "set HSB_SHARD_FIRST to the array's first index, or " + use_explicit);
}

// PBS Pro (qsub -J A-B:S) and Torque (qsub -t A-B) tell a task its index
// only: the user says the range, HSB_SHARD_FIRST (default 0),
// HSB_SHARD_STEP (default 1) and HSB_SHARD_COUNT.
SchedulerShare pbs_share(const Environment& environment, const std::string& scheduler, const std::string& variable,
                         const std::string& submit) {
  const long long index = required_number(environment, variable, 0, "");
  const long long count =
      required_number(environment, "HSB_SHARD_COUNT", 1,
                      scheduler +
                          " does not tell a task its array's range: set HSB_SHARD_COUNT to the number of indices, "
                          "HSB_SHARD_FIRST to the first (default 0) and HSB_SHARD_STEP to the step (default 1)");
  const long long first = optional_number(environment, "HSB_SHARD_FIRST", 0).value_or(0);
  const long long step = optional_number(environment, "HSB_SHARD_STEP", 1).value_or(1);
  return share_of_task(scheduler + " array index " + text(index), variable, index, {first, step, count},
                       "HSB_SHARD_FIRST (default 0), HSB_SHARD_STEP (default 1) and HSB_SHARD_COUNT",
                       "set them to the array's range (" + submit + ": HSB_SHARD_FIRST=1, HSB_SHARD_COUNT=16)");
}

SchedulerShare pbs_pro_share(const Environment& environment) {
  return pbs_share(environment, "PBS Pro", "PBS_ARRAY_INDEX", "qsub -J 1-16");
}

SchedulerShare torque_share(const Environment& environment) {
  return pbs_share(environment, "Torque", "PBS_ARRAYID", "qsub -t 1-16");
}

// A pod of an Indexed Job knows its index but not the Job's completions.
SchedulerShare kubernetes_share(const Environment& environment) {
  const long long index = required_number(environment, "JOB_COMPLETION_INDEX", 0, "");
  const long long count =
      required_number(environment, "HSB_SHARD_COUNT", 1,
                      "a Kubernetes Indexed Job does not tell its pods its completions: set HSB_SHARD_COUNT to them");
  return share_of_task("Kubernetes completion index " + text(index), "JOB_COMPLETION_INDEX", index, {0, 1, count},
                       "HSB_SHARD_COUNT", "set HSB_SHARD_COUNT to the Job's completions");
}

SchedulerShare aws_batch_share(const Environment& environment) {
  const long long index = required_number(environment, "AWS_BATCH_JOB_ARRAY_INDEX", 0, "");
  const std::optional<long long> size = optional_number(environment, "AWS_BATCH_JOB_ARRAY_SIZE", 1);
  const std::optional<long long> given = optional_number(environment, "HSB_SHARD_COUNT", 1);
  if (size && given && *size != *given)
    refuse("HSB_SHARD_COUNT=" + text(*given) + " disagrees with AWS_BATCH_JOB_ARRAY_SIZE=" + text(*size));
  if (!size && !given)
    refuse("HSB_SHARD_COUNT is not set, nor AWS_BATCH_JOB_ARRAY_SIZE: set HSB_SHARD_COUNT to the array job's size");
  return share_of_task("AWS Batch array index " + text(index), "AWS_BATCH_JOB_ARRAY_INDEX", index,
                       {0, 1, size ? *size : *given}, "AWS_BATCH_JOB_ARRAY_SIZE or HSB_SHARD_COUNT",
                       "set HSB_SHARD_COUNT to the array job's size");
}

// The schedulers, each by the variable that holds an array task's index.
struct ArrayTask {
  const char* scheduler;
  const char* index;
  const char* not_array;  // the index's value in a job that is not an array, if it has one
  SchedulerShare (*share)(const Environment&);
};
const ArrayTask array_tasks[] = {
    {"Slurm", "SLURM_ARRAY_TASK_ID", nullptr, slurm_share},
    {"Grid Engine", "SGE_TASK_ID", "undefined", grid_engine_share},
    {"LSF", "LSB_JOBINDEX", "0", lsf_share},
    {"PBS Pro", "PBS_ARRAY_INDEX", nullptr, pbs_pro_share},
    {"Torque", "PBS_ARRAYID", nullptr, torque_share},
    {"Kubernetes Indexed Job", "JOB_COMPLETION_INDEX", nullptr, kubernetes_share},
    {"AWS Batch", "AWS_BATCH_JOB_ARRAY_INDEX", nullptr, aws_batch_share},
};

// Jobs that are not arrays, by a variable each has (with its value, when
// that is what says so), and how to submit one that is.
struct PlainJob {
  const char* what;
  const char* variable;
  const char* value;  // nullptr: any
  const char* submit;
};
const PlainJob plain_jobs[] = {
    {"a Slurm job", "SLURM_JOB_ID", nullptr, "sbatch --array=0-15"},
    {"a Grid Engine job", "SGE_TASK_ID", "undefined", "qsub -t 1-16"},
    {"an LSF job", "LSB_JOBINDEX", "0", "bsub -J \"hsb[1-16]\""},
    {"a PBS Pro or Torque job", "PBS_JOBID", nullptr, "qsub -J 1-16, or -t 1-16 with Torque"},
    {"an AWS Batch job", "AWS_BATCH_JOB_ID", nullptr, "an array job"},
};

}  // namespace

SchedulerShare scheduler_share(const Environment& environment) {
  std::vector<const ArrayTask*> found;
  for (const ArrayTask& task : array_tasks) {
    const std::string* value = find(environment, task.index);
    if (value && !(task.not_array && *value == task.not_array)) found.push_back(&task);
  }
  if (find(environment, "HSB_SHARD_INDEX")) {
    // The log says what it overrode: an HSB_SHARD_INDEX the submitting
    // shell exported to every task would give them all one share.
    SchedulerShare share = explicit_share(environment);
    for (const ArrayTask* task : found)
      share.origin += std::string(" (over ") + task->index + "=" + *find(environment, task->index) + ")";
    return share;
  }
  // Two at once (a job of one scheduler started from another's): taking
  // either might take the wrong array's place.
  if (found.size() > 1)
    refuse(std::string(found[0]->index) + " (" + found[0]->scheduler + ") and " + found[1]->index + " (" +
           found[1]->scheduler + ") are both set, so which array this task belongs to is unclear: " + use_explicit);
  if (found.size() == 1) return found.front()->share(environment);
  for (const PlainJob& job : plain_jobs) {
    const std::string* value = find(environment, job.variable);
    if (value && (!job.value || *value == job.value))
      refuse(std::string(job.what) + " that is not an array (" + job.variable +
             (job.value ? "=" + *value : std::string(" is set, no array index is")) + "): submit it as one (" +
             job.submit + "), or give --shard K/N");
  }
  std::string looked_for = "HSB_SHARD_INDEX (any scheduler, with HSB_SHARD_COUNT)";
  for (const ArrayTask& task : array_tasks) looked_for += std::string(", ") + task.index + " (" + task.scheduler + ")";
  refuse("no job array task found: looked for " + looked_for + "; outside a job array give --shard K/N");
}

SchedulerShare scheduler_share_of_process() {
  Environment environment;
  for (char** entry = environ; entry && *entry; ++entry) {
    const std::string assignment = *entry;
    const std::size_t eq = assignment.find('=');
    // The first of a name given twice, as getenv() reads it.
    if (eq != std::string::npos) environment.emplace(assignment.substr(0, eq), assignment.substr(eq + 1));
  }
  return scheduler_share(environment);
}

}  // namespace hsb
