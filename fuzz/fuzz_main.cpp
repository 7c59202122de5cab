// A libFuzzer target around one entry of entries.hpp; COLLIDESCOPE_FUZZ_TARGET names it.

#include "entries.hpp"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const collidescope::fuzz::Entry entry = collidescope::fuzz::entry_named(COLLIDESCOPE_FUZZ_TARGET);
    if (entry == nullptr) std::abort();
    entry({reinterpret_cast<const std::byte*>(data), size});
    return 0;
}
