#pragma once
// Where a data output goes: a file, or stdout for `-`.

#include <fstream>
#include <ostream>
#include <string>

namespace collidescope::app {

/// An output named on the command line: `-` is stdout, anything else a file (truncated).
class OutputStream {
public:
    /// Opens `target`. Throws InputError naming it when the file cannot be created.
    explicit OutputStream(const std::string& target);

    std::ostream& stream() { return m_to_stdout ? *m_stdout : m_file; }
    /// Flushes; throws std::runtime_error naming the target when anything failed to write.
    void finish();

private:
    std::string m_target;
    bool m_to_stdout;
    std::ostream* m_stdout = nullptr;
    std::ofstream m_file;
};

}  // namespace collidescope::app
