// LD_PRELOADed by the sanitizer suite (scripts/sanitize.sh), nowhere else.
//
// The Vulkan loader dlcloses the driver (Mesa's lavapipe) and the validation layer when an
// instance is destroyed. Memory those libraries still hold from their own globals then looks
// leaked to LeakSanitizer, which reports it from "<unknown module>": the library is gone, so
// there is no name to suppress it by, and a suppression of every unknown module would hide
// our leaks too. Keeping exactly these libraries mapped (dlclose of them does nothing) keeps
// their memory reachable, and whatever is still reported names its library.
#include <dlfcn.h>
#include <link.h>

#include <cstring>

extern "C" int dlclose(void* handle) {
    using Close = int (*)(void*);
    static const Close real = reinterpret_cast<Close>(dlsym(RTLD_NEXT, "dlclose"));
    link_map* map = nullptr;
    if (dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map && map->l_name &&
        (std::strstr(map->l_name, "libvulkan_") || std::strstr(map->l_name, "libVkLayer_")))
        return 0;
    return real ? real(handle) : 0;
}
