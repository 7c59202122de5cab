#pragma once
/// COLLIDESCOPE_API marks what libcollidescope exports: the facade's classes. Everything else
/// in the library (the engine, the recorder, the facade's internals) stays hidden.

#define COLLIDESCOPE_API __attribute__((visibility("default")))
