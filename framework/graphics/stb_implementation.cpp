// The implementations of stb_image and stb_image_write, compiled here only where stb is installed as
// headers alone (vcpkg, Homebrew: PBA_STB_HEADER_ONLY). Debian's libstb already contains them.
#if defined(PBA_STB_HEADER_ONLY)
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
#endif
