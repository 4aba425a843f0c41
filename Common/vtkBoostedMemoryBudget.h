/**
 * @class   vtkBoostedMemoryBudget
 * @brief   the one memory budget of the project's updates: estimate first, refuse politely
 *
 * Every update (a grid source, the dipole field, the deformation filter's conversion of an image
 * or a rectilinear grid) estimates the bytes it will allocate before allocating any of them and
 * is refused, with one error and an empty output, when the estimate exceeds the budget.
 *
 * The budget: the environment variable BOOSTEDSURFACES_MEMORY_BUDGET when it is set and not
 * empty, in bytes ("2000000000") or with a binary unit suffix, case-insensitive, optionally
 * followed by "B" or "iB" ("512M", "8GiB", "1.5T"); otherwise half of the machine's physical
 * memory (12 GiB on a 24 GiB machine; 8 GiB when the physical memory is unknown). Half, because
 * an update's peak is not the whole story: the pipeline keeps the previous output until the new one replaces it, and
 * ParaView's rendering copies the points again. A value that cannot be read is an error of every
 * update (not a silent default). The variable is read at each update, so a running session may
 * change it.
 *
 * Allocation can still fail below the budget (an address-space limit such as `ulimit -v`, other
 * processes). VTK's arrays abort the process then (the abort() branch of vtkGenericDataArray, as
 * Debian builds VTK), so Problem also probes: it allocates the whole estimate once and frees it
 * (address space only, no page is touched), and a failed probe is the same kind of error. Run
 * turns a std::bad_alloc (std::vector, or a VTK built to throw) into an error too, so no update
 * aborts the process.
 */
#ifndef vtkBoostedMemoryBudget_h
#define vtkBoostedMemoryBudget_h

#include "BoostedSurfacesCommonModule.h" // for export macro

#include <functional> // for Run
#include <string>     // for the problems

class vtkAlgorithm;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedMemoryBudget
{
public:
  /// The name of the environment variable that overrides the default budget.
  static constexpr const char* EnvironmentVariable = "BOOSTEDSURFACES_MEMORY_BUDGET";

  /// The budget in bytes, or -1 with `problem` set when the environment variable is invalid.
  static double Bytes(std::string& problem);

  /// The default budget: half of the physical memory.
  static double DefaultBytes();

  /// Reads "123", "1.5e9", "512M", "8GiB", "2tb" (binary multiples); -1 when `text` is not a
  /// finite positive size.
  static double Parse(const std::string& text);

  /// Empty when an update of `bytes` fits the budget and the process can allocate that much now
  /// (the probe), otherwise the error to report; `what` names the work ("the twistor mesh of
  /// 1000 x 1001 samples").
  static std::string Problem(double bytes, const std::string& what);

  /// Runs `work`; a std::bad_alloc becomes an error of `algorithm` and false (the caller empties
  /// its output). True when `work` ran to its end.
  static bool Run(vtkAlgorithm* algorithm, const std::function<void()>& work);

  /// "12.0 GiB", "512 MiB": a size for messages.
  static std::string Format(double bytes);
};

#endif
