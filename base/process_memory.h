#pragma once
// This process's memory, from /proc/self/status (Linux); 0 where unknown.

namespace hsb {

double resident_bytes();       // VmRSS
double peak_resident_bytes();  // VmHWM: the high-water mark
double virtual_bytes();        // VmSize: what counts against RLIMIT_AS
double file_resident_bytes();  // RssFile: the resident pages of mapped files (libraries' code among them)
// Starts a new high-water mark at the current resident size (Linux ≥ 4.0),
// so a measurement's peak is its own.
void reset_peak_resident();

}  // namespace hsb
