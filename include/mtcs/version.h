#pragma once
// The program's name and version, for --version, run stores and file headers. CMakeLists.txt
// refuses to configure when it differs from project()'s version.
namespace mtcs {
inline constexpr const char* kProgram = "mtcs 0.1.0";
}  // namespace mtcs
