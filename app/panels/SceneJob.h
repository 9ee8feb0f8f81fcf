#pragma once
// Loading a scene file on a worker thread (std::jthread), so the window keeps drawing while a large
// glTF parses. The job only loads and checks; the solver thread meshes and solves what it returns.
// The UI polls it and takes the finished result once; starting a new job abandons the one running.
// Errors come back as text and leave the caller's scene untouched.
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "radiometry/scene/Scene.h"

namespace radiant::app {

struct SceneJobResult {
    std::shared_ptr<const Scene> scene;  ///< null when loading failed; its warnings in Scene::warnings
    std::string error;  ///< the RadiantError's one line, when it failed
};

class SceneJob {
public:
    SceneJob() = default;
    ~SceneJob();
    SceneJob(const SceneJob&) = delete;
    SceneJob& operator=(const SceneJob&) = delete;

    /// Starts loading `nameOrPath` (a built-in name or a .gltf/.glb path); a job still running is
    /// waited for and its result dropped (loaders cannot be interrupted, and are quick for files a
    /// class uses).
    void start(const std::string& nameOrPath);
    [[nodiscard]] bool running() const;
    [[nodiscard]] const std::string& what() const { return what_; }
    /// The finished job's result, once.
    std::optional<SceneJobResult> take();

private:
    std::string what_;
    mutable std::mutex mutex_;
    std::optional<SceneJobResult> finished_;
    bool running_ = false;
    std::jthread worker_;  // last: joined before the state it writes is destroyed
};

} // namespace radiant::app
