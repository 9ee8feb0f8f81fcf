#pragma once
// Loading and meshing a scene on a worker thread (std::jthread), so the window keeps drawing.
// The UI polls progress through atomics and takes the finished result once; starting a new job
// cancels the one running. Errors come back as text and leave the caller's scene untouched.
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "radiometry/common/Progress.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"

namespace radiant::app {

struct SceneJobResult {
    std::optional<Scene> scene;  ///< empty when the job failed
    PatchMesh mesh;
    double maxPatchArea = 0;     ///< m^2, the meshing it was made with
    std::vector<std::string> warnings;
    std::string error;           ///< the RadiantError's one line, when it failed
};

class SceneJob {
public:
    /// What a job does on the worker: produce a scene and its mesh, reporting through Progress.
    using Work = std::function<SceneJobResult(Progress&)>;

    SceneJob() = default;
    ~SceneJob();
    SceneJob(const SceneJob&) = delete;
    SceneJob& operator=(const SceneJob&) = delete;

    /// Cancels any running job (waiting for it to notice) and starts `work`; `what` names it in the UI.
    void start(std::string what, Work work);
    void cancel();
    [[nodiscard]] bool running() const;
    [[nodiscard]] double fraction() const;
    [[nodiscard]] const std::string& what() const { return what_; }
    /// The finished job's result, once.
    std::optional<SceneJobResult> take();

private:
    std::shared_ptr<Progress> progress_;
    std::string what_;
    mutable std::mutex mutex_;
    std::optional<SceneJobResult> finished_;
    bool running_ = false;
    std::jthread worker_;  // last: joined before the state it writes is destroyed
};

/// Loads `nameOrPath` (built-in name or glTF path) and meshes it at `maxPatchArea` m^2.
SceneJob::Work loadAndMesh(std::string nameOrPath, double maxPatchArea);
/// Re-meshes an already loaded scene at `maxPatchArea` m^2.
SceneJob::Work remesh(Scene scene, double maxPatchArea);

} // namespace radiant::app
