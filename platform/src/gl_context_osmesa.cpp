// The OSMesa context: an OpenGL 4.5 core profile over a tiny RGBA buffer (the cull renders into
// its own framebuffer objects; the window-system buffer only has to exist). libOSMesa is
// opened at the first context (collidescope/shared_library.hpp), not linked: it loads Mesa's
// LLVM, which a command that renders nothing should not pay for. GL entry points come from
// OSMesaGetProcAddress.

#include "collidescope/gl_api.hpp"
#include "collidescope/gl_context.hpp"

#include "collidescope/error.hpp"
#include "collidescope/shared_library.hpp"

#include <GL/osmesa.h>

#include <array>
#include <string>
#include <type_traits>
#include <variant>

namespace collidescope::gl {
namespace {

// The four OSMesa functions the context calls, from libOSMesa.so.8 (Mesa 22's soname).
struct OsmesaFunctions {
    decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
    decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaDestroyContext) destroy_context = nullptr;
};

// Loaded once per process; a failure (no Mesa) is kept and thrown at every context.
const OsmesaFunctions& osmesa() {
    using Loaded = std::variant<OsmesaFunctions, std::string>;
    static const Loaded loaded = []() -> Loaded {
        try {
            const SharedLibrary library("libOSMesa.so.8");
            const auto load = [&](auto& slot, const char* name) {
                slot = library.function<std::remove_reference_t<decltype(slot)>>(name);
            };
            OsmesaFunctions functions;
            load(functions.create_context_attribs, "OSMesaCreateContextAttribs");
            load(functions.get_proc_address, "OSMesaGetProcAddress");
            load(functions.make_current, "OSMesaMakeCurrent");
            load(functions.destroy_context, "OSMesaDestroyContext");
            return functions;
        } catch (const UnavailableError& error) {
            return std::string("OSMesa: ") + error.what();
        }
    }();
    if (const auto* reason = std::get_if<std::string>(&loaded)) throw UnavailableError(*reason);
    return std::get<OsmesaFunctions>(loaded);
}

class OsmesaContext final : public GlContext {
public:
    OsmesaContext() {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        m_context = osmesa().create_context_attribs(attributes, nullptr);
        if (m_context == nullptr) throw UnavailableError("OSMesa: could not create an OpenGL 4.5 core context");
        try {
            m_api = load_gl_api(osmesa().get_proc_address, "OSMesa");
            make_current();
        } catch (...) {
            osmesa().destroy_context(m_context);
            throw;
        }
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        m_renderer = std::string(renderer != nullptr ? renderer : "unknown") + " via OSMesa";
    }
    ~OsmesaContext() override {
        if (current_gl_api() == &m_api) current_gl_api() = nullptr;
        osmesa().destroy_context(m_context);
    }
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    void make_current() override {
        if (osmesa().make_current(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, k_size, k_size) == 0) {
            throw UnavailableError("OSMesa: OSMesaMakeCurrent failed");
        }
        current_gl_api() = &m_api;
    }
    std::string renderer() const override { return m_renderer; }
    GlBackend backend() const override { return GlBackend::Osmesa; }

private:
    static constexpr int k_size = 4;
    OSMesaContext m_context = nullptr;
    std::array<unsigned char, 4 * k_size * k_size> m_buffer{};
    GlApi m_api;
    std::string m_renderer;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace collidescope::gl
