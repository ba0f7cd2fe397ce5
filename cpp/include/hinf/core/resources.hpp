// Limits on what one computation may allocate, checked before allocating.
#pragma once

#include <cstddef>
#include <string>

namespace hinf {

// Bytes of physical memory of this machine (0 if unknown).
std::size_t physical_memory_bytes();
// The share of the physical memory one run may use for its stored results: a quarter.
std::size_t memory_budget_bytes();
// InputError when `bytes` exceed memory_budget_bytes(): "<what> would need X GB, more than a
// quarter of this machine's memory (Y GB): <advice>".
void check_memory(double bytes, const std::string& what, const std::string& advice);

}  // namespace hinf
