// Sanitizer builds only (AVS_SANITIZE): keeps Mesa's software DRI driver loaded until the
// process ends.
//
// Mesa unloads its driver (dlclose) when the last GL context goes. The driver's long-lived
// allocations, reachable from its globals until then, look leaked to LeakSanitizer, which scans
// after the unload and cannot even name the unmapped frames (128 + 2 x 56 bytes per context,
// "<unknown module>"). With the driver opened once more here with RTLD_NODELETE it stays
// mapped, its memory stays reachable, and no suppression is needed: LeakSanitizer still sees
// every allocation that is really lost, Mesa's included.
#include <dlfcn.h>

#include <string>

namespace
{
struct KeepGLDriverLoaded
{
  KeepGLDriverLoaded()
  {
    const std::string driver = std::string(AVS_DRI_DRIVER_DIR) + "/swrast_dri.so";
    dlopen(driver.c_str(), RTLD_LAZY | RTLD_LOCAL | RTLD_NODELETE); // absent: nothing to keep
  }
} keep;
} // namespace
