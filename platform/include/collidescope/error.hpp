#pragma once
/// Errors the engine raises on bad input at its public entry points.
///
/// The library never prints and never exits: it throws InputError with a message that names
/// the file and the element (frame, object, vertex or face index, line or byte offset); the
/// app catches it at main, prints the one line and exits 2.

#include <stdexcept>
#include <string>

namespace collidescope {

/// Bad input: unreadable, malformed or inconsistent data. what() is one line, no newline.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A capability the running machine lacks (no GL context, a missing data package).
class UnavailableError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace collidescope
