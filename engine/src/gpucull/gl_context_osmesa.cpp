// The OSMesa context: an OpenGL 4.5 core profile over a tiny RGBA buffer (the cull renders into
// its own framebuffer objects; the window-system buffer only has to exist). Entry points come
// from OSMesaGetProcAddress.

#include "collidescope/gl_api.hpp"
#include "gpucull/cull_context.hpp"

#include "collidescope/error.hpp"

#include <GL/osmesa.h>

#include <array>

namespace collidescope::gpucull {
namespace {

class OsmesaContext final : public GlContext {
public:
    OsmesaContext() {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        m_context = OSMesaCreateContextAttribs(attributes, nullptr);
        if (m_context == nullptr) throw UnavailableError("OSMesa: could not create an OpenGL 4.5 core context");
        try {
            m_api = load_gl_api(OSMesaGetProcAddress, "OSMesa");
            make_current();
        } catch (...) {
            OSMesaDestroyContext(m_context);
            throw;
        }
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        m_renderer = std::string(renderer != nullptr ? renderer : "unknown") + " via OSMesa";
    }
    ~OsmesaContext() override {
        if (current_gl_api() == &m_api) current_gl_api() = nullptr;
        OSMesaDestroyContext(m_context);
    }
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    void make_current() override {
        if (OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, k_size, k_size) == 0) {
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

}  // namespace collidescope::gpucull
