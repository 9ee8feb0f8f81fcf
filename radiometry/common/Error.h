#pragma once
// Errors that say where and what: the file, the element inside it, and the offending values
// (as pbrt's ErrorExit(FileLoc, ...)). Thrown by loaders and checked inputs; the app catches them,
// shows the one-line message and keeps its previous state.
#include <stdexcept>
#include <string>
#include <utility>

namespace radiant {

/// Where in an input a problem lies: "scene.gltf" + "mesh 3, primitive 0".
struct SourceLocation {
    std::string file;     ///< path as the user gave it, or a built-in scene's name
    std::string element;  ///< e.g. "mesh 3, primitive 0", "--max-patch-area"; may be empty

    [[nodiscard]] std::string str() const {
        if (element.empty()) return file;
        if (file.empty()) return element;
        return file + ": " + element;
    }
};

class RadiantError : public std::runtime_error {
public:
    RadiantError(SourceLocation where, const std::string& what)
        : std::runtime_error(where.str().empty() ? what : where.str() + ": " + what),
          where_(std::move(where)), detail_(what) {}
    [[nodiscard]] const SourceLocation& where() const { return where_; }
    /// The message without the location prefix.
    [[nodiscard]] const std::string& detail() const { return detail_; }

private:
    SourceLocation where_;
    std::string detail_;
};

/// Thrown when the user's request exceeds a configured budget (triangles, patches, memory).
class BudgetError : public RadiantError {
public:
    using RadiantError::RadiantError;
};

/// Thrown by long work when it was cancelled (for example by a newer command).
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

} // namespace radiant
