#include "app/panels/SceneJob.h"

#include <cstdio>
#include <exception>

#include "radiometry/scene/SceneLibrary.h"

namespace radiant::app {

SceneJob::~SceneJob() {
    if (worker_.joinable()) worker_.join();
}

void SceneJob::start(const std::string& nameOrPath) {
    if (worker_.joinable()) worker_.join();
    {
        std::scoped_lock lock(mutex_);
        finished_.reset();
        running_ = true;
    }
    what_ = "loading " + nameOrPath;
    worker_ = std::jthread([this, nameOrPath] {
        SceneJobResult result;
        try {
            LoadedScene loaded = loadScene(nameOrPath);
            // As on the command line; the Scene panel shows them from the scene too.
            for (const std::string& warning : loaded.scene.warnings) std::fprintf(stderr, "radiant: warning: %s\n", warning.c_str());
            result.scene = std::make_shared<const Scene>(std::move(loaded.scene));
        } catch (const std::exception& e) {
            result.error = e.what();
        }
        std::scoped_lock lock(mutex_);
        running_ = false;
        finished_ = std::move(result);
    });
}

bool SceneJob::running() const {
    std::scoped_lock lock(mutex_);
    return running_;
}

std::optional<SceneJobResult> SceneJob::take() {
    std::scoped_lock lock(mutex_);
    std::optional<SceneJobResult> result = std::move(finished_);
    finished_.reset();
    return result;
}

} // namespace radiant::app
