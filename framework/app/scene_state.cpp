#include "app/scene_state.h"

#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
// In the ASan runtime of GCC and clang alike; only clang ships <sanitizer/allocator_interface.h>.
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pba::app {

std::size_t heapBytesInUse() {
#if defined(__SANITIZE_ADDRESS__)
  return __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;  // small blocks in the arenas and large blocks mapped on their own
#else
  return 0;
#endif
}

}  // namespace pba::app
