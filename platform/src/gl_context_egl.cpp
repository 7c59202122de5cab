// The EGL context: OpenGL 4.5 core without a window. The display is an EGL device
// (EGL_EXT_platform_device): a GPU's when the driver offers one, else Mesa's software device;
// without device enumeration, Mesa's surfaceless platform. The context is made current with no
// surface where EGL_KHR_surfaceless_context allows it, on a 1x1 pbuffer otherwise (rendering
// goes to framebuffer objects either way). Entry points come from eglGetProcAddress.

#include "collidescope/gl_api.hpp"
#include "collidescope/gl_context.hpp"

#include "collidescope/error.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace collidescope::gl {
namespace {

std::string egl_error(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    return std::string("EGL: ") + what + " failed (" + code + ")";
}

bool has_extension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t length = std::strlen(name);
    for (const char* at = std::strstr(list, name); at != nullptr; at = std::strstr(at + 1, name)) {
        const bool starts = at == list || at[-1] == ' ';
        const bool ends = at[length] == '\0' || at[length] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

template <class Function>
Function egl_function(const char* name) {
    return reinterpret_cast<Function>(eglGetProcAddress(name));
}

// The EGL devices, hardware ones first (Mesa's software device last); empty without
// EGL_EXT_device_enumeration.
std::vector<EGLDeviceEXT> devices_hardware_first(bool& any_hardware) {
    any_hardware = false;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client, "EGL_EXT_device_enumeration") || !has_extension(client, "EGL_EXT_platform_device")) {
        return {};
    }
    const auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    const auto query_string = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    EGLint count = 0;
    if (query_devices == nullptr || query_string == nullptr || query_devices(0, nullptr, &count) != EGL_TRUE) return {};
    std::vector<EGLDeviceEXT> all(static_cast<std::size_t>(count));
    if (count == 0 || query_devices(count, all.data(), &count) != EGL_TRUE) return {};
    std::vector<EGLDeviceEXT> hardware, software;
    for (EGLDeviceEXT device : all) {
        const bool is_software = has_extension(query_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
        (is_software ? software : hardware).push_back(device);
    }
    any_hardware = !hardware.empty();
    hardware.insert(hardware.end(), software.begin(), software.end());
    return hardware;
}

// One initialised display for the process (EGL displays are shared by all threads; never
// terminated, since contexts of other threads may outlive any one owner).
struct Display {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string failure;  // why there is none
};

const Display& process_display() {
    static Display result;
    static std::once_flag once;
    std::call_once(once, [] {
        const auto platform_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
        std::vector<EGLDisplay> candidates;
        bool any_hardware = false;
        if (platform_display != nullptr) {
            for (EGLDeviceEXT device : devices_hardware_first(any_hardware)) {
                candidates.push_back(platform_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
            }
            const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
            if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
                candidates.push_back(platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
            }
        }
        std::string failure = "EGL: no device or surfaceless display";
        for (EGLDisplay display : candidates) {
            if (display == EGL_NO_DISPLAY) continue;
            EGLint major = 0, minor = 0;
            if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
                failure = egl_error("eglInitialize");
                continue;
            }
            if (major == 1 && minor < 4) {
                failure = "EGL: version " + std::to_string(major) + "." + std::to_string(minor) + " (1.4 needed)";
                continue;
            }
            result.display = display;
            return;
        }
        result.failure = failure;
    });
    return result;
}

class EglContext final : public GlContext {
public:
    EglContext() {
        const Display& display = process_display();
        if (display.display == EGL_NO_DISPLAY) throw UnavailableError(display.failure);
        m_display = display.display;
        if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) throw UnavailableError(egl_error("eglBindAPI(OpenGL)"));
        const EGLConfig config = choose_config();
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        m_context = eglCreateContext(m_display, config, EGL_NO_CONTEXT, attributes);
        if (m_context == EGL_NO_CONTEXT) throw UnavailableError(egl_error("creating an OpenGL 4.5 core context"));
        try {
            if (!has_extension(eglQueryString(m_display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
                const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
                m_surface = eglCreatePbufferSurface(m_display, config, size);
                if (m_surface == EGL_NO_SURFACE) throw UnavailableError(egl_error("eglCreatePbufferSurface"));
            }
            m_api = load_gl_api(eglGetProcAddress, "EGL");
            make_current();
        } catch (...) {
            release();
            throw;
        }
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        m_renderer = std::string(renderer != nullptr ? renderer : "unknown") + " via EGL";
    }
    ~EglContext() override { release(); }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    void make_current() override {
        if (eglMakeCurrent(m_display, m_surface, m_surface, m_context) != EGL_TRUE) {
            throw UnavailableError(egl_error("eglMakeCurrent"));
        }
        current_gl_api() = &m_api;
    }
    std::string renderer() const override { return m_renderer; }
    GlBackend backend() const override { return GlBackend::Egl; }

private:
    // A config for OpenGL with pbuffers; none is needed with EGL_KHR_no_config_context.
    EGLConfig choose_config() const {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (eglChooseConfig(m_display, wanted, &config, 1, &count) == EGL_TRUE && count > 0) return config;
        if (has_extension(eglQueryString(m_display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
            return EGL_NO_CONFIG_KHR;
        }
        throw UnavailableError("EGL: no config for OpenGL with pbuffers");
    }

    void release() {
        if (current_gl_api() == &m_api) current_gl_api() = nullptr;
        if (eglGetCurrentContext() == m_context) eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (m_surface != EGL_NO_SURFACE) eglDestroySurface(m_display, m_surface);
        if (m_context != EGL_NO_CONTEXT) eglDestroyContext(m_display, m_context);
    }

    EGLDisplay m_display = EGL_NO_DISPLAY;
    EGLContext m_context = EGL_NO_CONTEXT;
    EGLSurface m_surface = EGL_NO_SURFACE;
    GlApi m_api;
    std::string m_renderer;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context() { return std::make_unique<EglContext>(); }

bool egl_hardware_device_present() {
    bool any_hardware = false;
    devices_hardware_first(any_hardware);
    return any_hardware;
}

}  // namespace collidescope::gl
