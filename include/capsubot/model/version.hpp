#pragma once
// The library's version (the CMake project version), e.g. for provenance lines.

namespace capsubot {

/// "MAJOR.MINOR.PATCH" of the library that is linked.
const char* Version();

}  // namespace capsubot
