#pragma once
// `--shard auto`: the share of the batch a job array task renders, read
// from the variables the scheduler that started it sets.
//
// Every scheduler numbers an array's tasks first, first + step, …,
// first + (count − 1)·step; the task with index first + (K − 1)·step takes
// share K of count. So the tasks of one array take every share exactly
// once, whatever the range starts at and however it steps, and a task
// refuses (never guesses) when its variables do not describe such a range:
// a task that guessed wrong would render another's share, or none, and
// the images no task rendered stay missing however often the array is
// resubmitted.
//
//   HSB_SHARD_INDEX + HSB_SHARD_COUNT  any scheduler (HTCondor: $(Process)); index from 0; override the rest
//   Slurm        SLURM_ARRAY_TASK_ID, _MIN, _MAX, _STEP, _COUNT: any range A-B:S; an index list
//                (--array=1,3,7) is refused, a task's rank in it is not in its variables
//   Grid Engine  SGE_TASK_ID, SGE_TASK_FIRST, SGE_TASK_LAST, SGE_TASK_STEPSIZE (SGE, Univa, Altair)
//   LSF          LSB_JOBINDEX, LSB_JOBINDEX_STEP, LSB_JOBINDEX_END and/or HSB_SHARD_COUNT (both: they
//                must agree); LSF does not say where the range starts: HSB_SHARD_FIRST, default 1
//   PBS Pro      PBS_ARRAY_INDEX }  with HSB_SHARD_COUNT, HSB_SHARD_FIRST (default 0) and
//   Torque       PBS_ARRAYID     }  HSB_SHARD_STEP (default 1): neither says its array's range
//   Kubernetes   JOB_COMPLETION_INDEX (from 0) with HSB_SHARD_COUNT (the Job's completions)
//   AWS Batch    AWS_BATCH_JOB_ARRAY_INDEX (from 0) with AWS_BATCH_JOB_ARRAY_SIZE and/or HSB_SHARD_COUNT

#include <map>
#include <string>

#include "renderer/app/batch.h"

namespace hsb {

struct SchedulerShare {
  Shard shard;
  // Where the share came from, for the log: "Slurm array task 4 of 0-6:2: share 3/4".
  std::string origin;
};

// The share `environment` (variable → value) gives. Throws
// std::invalid_argument, its message starting "--shard auto: ", when it
// gives none: no array task found (naming every variable looked for), a
// job that is not an array, two schedulers' arrays at once, a variable
// missing (naming it) or bad (naming it and its value), an index list.
SchedulerShare scheduler_share(const std::map<std::string, std::string>& environment);

// The same from this process's environment.
SchedulerShare scheduler_share_of_process();

}  // namespace hsb
