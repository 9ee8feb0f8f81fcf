// LeakSanitizer looks for leaks at exit, after glfwTerminate has unloaded the OpenGL libraries.
// Mesa keeps a few blocks until exit, and by then the code that allocated them is gone: the report
// says "<unknown module>", which no suppression can name, and every gl test would fail on 240 bytes
// that are not ours. So, in sanitizer builds only, the gl tests load those libraries once more at
// start-up and never unload them: the report then names the library and scripts/lsan.supp, which
// lists system libraries only, can suppress it. Radiant's own allocations stay fully checked.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#define RADIANT_CHECKS_LEAKS 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define RADIANT_CHECKS_LEAKS 1
#endif

#ifdef RADIANT_CHECKS_LEAKS

#include <dlfcn.h>
#include <link.h>

#include <filesystem>

namespace {

/// Loads `library` (a name on the loader's path or an absolute path) for good; null if absent.
void* loadForGood(const char* library) {
    return dlopen(library, RTLD_NOW | RTLD_GLOBAL | RTLD_NODELETE);
}

struct KeepGlLibrariesLoaded {
    KeepGlLibrariesLoaded() {
        // glvnd's front ends and Mesa's GLX vendor library, which loads the driver.
        for (const char* library : {"libGLdispatch.so.0", "libGLX.so.0", "libGL.so.1", "libOpenGL.so.0"})
            loadForGood(library);
        void* mesa = loadForGood("libGLX_mesa.so.0");
        if (!mesa) return;
        // Mesa's drivers live in dri/ beside libGLX_mesa (one file under many names: whichever the
        // X server picks, the loader finds it already loaded); LIBGL_DRIVERS_PATH overrides that.
        link_map* map = nullptr;
        if (dlinfo(mesa, RTLD_DI_LINKMAP, &map) != 0 || !map || !map->l_name) return;
        const std::filesystem::path driver = std::filesystem::path(map->l_name).parent_path() / "dri" / "swrast_dri.so";
        loadForGood(driver.c_str());
    }
};

const KeepGlLibrariesLoaded keepGlLibrariesLoaded;

} // namespace

#endif
