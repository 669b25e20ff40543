#include "app/runner/scene_state.h"

#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
// In the ASan runtime of GCC and clang alike; only clang ships <sanitizer/allocator_interface.h>.
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__)
#include <malloc.h>
#elif defined(_WIN32)
#include <malloc.h>
#elif defined(__APPLE__)
#include <malloc/malloc.h>
#endif

namespace pba::app {

std::size_t heapBytesInUse() {
#if defined(__SANITIZE_ADDRESS__)
  return __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;  // small blocks in the arenas and large blocks mapped on their own
#elif defined(_WIN32)
  // The C runtime's heap, walked block by block: the sum of the blocks in use.
  _HEAPINFO entry{};
  entry._pentry = nullptr;
  std::size_t used = 0;
  while (_heapwalk(&entry) == _HEAPOK)
    if (entry._useflag == _USEDENTRY) used += entry._size;
  return used;
#elif defined(__APPLE__)
  return mstats().bytes_used;  // every malloc zone
#else
  return 0;
#endif
}

}  // namespace pba::app
