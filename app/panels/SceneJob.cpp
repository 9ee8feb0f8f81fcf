#include "app/panels/SceneJob.h"

#include <exception>

#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"

namespace radiant::app {

SceneJob::~SceneJob() { cancel(); }

void SceneJob::cancel() {
    if (progress_) progress_->cancelRequested = true;
    if (worker_.joinable()) worker_.join();
    std::scoped_lock lock(mutex_);
    running_ = false;
}

void SceneJob::start(std::string what, Work work) {
    cancel();
    {
        std::scoped_lock lock(mutex_);
        finished_.reset();
        running_ = true;
    }
    what_ = std::move(what);
    progress_ = std::make_shared<Progress>();
    worker_ = std::jthread([this, progress = progress_, work = std::move(work)] {
        SceneJobResult result;
        bool cancelled = false;
        try {
            result = work(*progress);
        } catch (const Cancelled&) {
            cancelled = true;
        } catch (const std::exception& e) {
            result.scene.reset();
            result.error = e.what();
        }
        std::scoped_lock lock(mutex_);
        running_ = false;
        if (!cancelled) finished_ = std::move(result);
    });
}

bool SceneJob::running() const {
    std::scoped_lock lock(mutex_);
    return running_;
}

double SceneJob::fraction() const { return progress_ ? progress_->fraction() : 0.0; }

std::optional<SceneJobResult> SceneJob::take() {
    std::scoped_lock lock(mutex_);
    std::optional<SceneJobResult> result = std::move(finished_);
    finished_.reset();
    return result;
}

SceneJob::Work loadAndMesh(std::string nameOrPath, double maxPatchArea) {
    return [nameOrPath = std::move(nameOrPath), maxPatchArea](Progress& progress) {
        LoadedScene loaded = loadScene(nameOrPath);
        progress.checkCancelled();
        SceneJobResult result;
        result.mesh = meshScene(loaded.scene, MeshingOptions{maxPatchArea}, &progress);
        result.maxPatchArea = maxPatchArea;
        result.warnings = std::move(loaded.warnings);
        result.scene = std::move(loaded.scene);
        return result;
    };
}

SceneJob::Work remesh(Scene scene, double maxPatchArea) {
    return [scene = std::move(scene), maxPatchArea](Progress& progress) {
        SceneJobResult result;
        result.mesh = meshScene(scene, MeshingOptions{maxPatchArea}, &progress);
        result.maxPatchArea = maxPatchArea;
        result.scene = scene;
        return result;
    };
}

} // namespace radiant::app
