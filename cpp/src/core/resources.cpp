#include "hinf/core/resources.hpp"

#include <unistd.h>

#include "hinf/core/errors.hpp"

namespace hinf {

std::size_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size);
}

std::size_t memory_budget_bytes() {
  const std::size_t total = physical_memory_bytes();
  // Unknown memory: assume a small machine (4 GiB).
  return (total > 0 ? total : (std::size_t{4} << 30)) / 4;
}

void check_memory(double bytes, const std::string& what, const std::string& advice) {
  const double budget = static_cast<double>(memory_budget_bytes());
  if (!(bytes <= budget))
    throw InputError(str_cat(what, " would need ", bytes / 1e9, " GB, more than a quarter of this machine's memory (",
                             4.0 * budget / 1e9, " GB): ", advice));
}

}  // namespace hinf
