#include "vtkBoostedMemoryBudget.h"

#include "vtkAlgorithm.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

#include <unistd.h>

double vtkBoostedMemoryBudget::DefaultBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && pageSize > 0)
  {
    return 0.5 * static_cast<double>(pages) * static_cast<double>(pageSize);
  }
  return 8.0 * 1024 * 1024 * 1024;
}

double vtkBoostedMemoryBudget::Parse(const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin)
  {
    return -1.0;
  }
  std::string unit(end);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back())))
  {
    unit.pop_back();
  }
  size_t first = 0;
  while (first < unit.size() && std::isspace(static_cast<unsigned char>(unit[first])))
  {
    ++first;
  }
  unit = unit.substr(first);
  for (char& c : unit)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  double scale = 1.0;
  if (!unit.empty())
  {
    const std::string prefixes = "kmgt";
    const size_t power = prefixes.find(unit[0]);
    if (power != std::string::npos)
    {
      scale = std::pow(1024.0, static_cast<double>(power + 1));
      unit = unit.substr(1);
    }
    if (!(unit.empty() || unit == "b" || (scale > 1.0 && unit == "ib")))
    {
      return -1.0;
    }
  }
  const double bytes = value * scale;
  return std::isfinite(bytes) && bytes > 0.0 ? bytes : -1.0;
}

double vtkBoostedMemoryBudget::Bytes(std::string& problem)
{
  const char* text = std::getenv(EnvironmentVariable);
  if (!text || !*text) // unset, or set to nothing (VAR= command): the default
  {
    return DefaultBytes();
  }
  const double bytes = Parse(text);
  if (bytes < 0.0)
  {
    problem = std::string(EnvironmentVariable) + " is '" + text +
      "', which is not a positive size: give bytes (2000000000) or a number with a unit "
      "K, M, G or T (512M, 8GiB), or unset it for the default (half of the physical memory)";
  }
  return bytes;
}

std::string vtkBoostedMemoryBudget::Format(double bytes)
{
  const char* units[] = { "bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB" };
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6)
  {
    bytes /= 1024.0;
    ++unit;
  }
  char text[64];
  std::snprintf(text, sizeof(text), unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

std::string vtkBoostedMemoryBudget::Problem(double bytes, const std::string& what)
{
  std::string problem;
  const double budget = Bytes(problem);
  if (!problem.empty())
  {
    return problem;
  }
  if (!(bytes <= budget)) // NaN or inf are never within the budget
  {
    return what + " needs about " + Format(bytes) + ", more than the memory budget of " +
      Format(budget) + " (" + EnvironmentVariable +
      ", default half of the physical memory): lower the resolution or request smaller pieces";
  }
  // The probe: one block of the whole estimate, freed at once. It only reserves address space
  // (no page is touched), and when it fails the update's own allocations would fail too; VTK's
  // arrays abort the process then instead of throwing (Debian's VTK is built without NDEBUG).
  void* probe = bytes > 0.0 && bytes < 9e18 ? std::malloc(static_cast<size_t>(bytes)) : nullptr;
  if (bytes > 0.0 && !probe)
  {
    return what + " needs about " + Format(bytes) +
      ", which this process cannot allocate now (an address-space limit or other processes): "
      "lower the resolution or request smaller pieces";
  }
  std::free(probe);
  return {};
}

bool vtkBoostedMemoryBudget::Run(vtkAlgorithm* algorithm, const std::function<void()>& work)
{
  try
  {
    work();
    return true;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(algorithm,
      << "out of memory: an allocation failed below the memory budget (an address-space limit "
         "or other processes); the output is empty. Lower the resolution or set "
      << EnvironmentVariable << " lower");
    return false;
  }
}
