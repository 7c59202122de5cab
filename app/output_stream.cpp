// Output files and stdout.

#include "output_stream.hpp"

#include "collidescope/error.hpp"

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>

namespace collidescope::app {

OutputStream::OutputStream(const std::string& target) : m_target(target), m_to_stdout(target == "-") {
    if (m_to_stdout) {
        m_stdout = &std::cout;
        return;
    }
    m_file.open(target, std::ios::binary | std::ios::trunc);
    if (!m_file) throw InputError(target + ": cannot create file (" + std::strerror(errno) + ")");
}

void OutputStream::finish() {
    std::ostream& out = stream();
    out.flush();
    if (!out) {
        throw std::runtime_error((m_to_stdout ? std::string("stdout") : m_target) + ": write failed");
    }
}

}  // namespace collidescope::app
