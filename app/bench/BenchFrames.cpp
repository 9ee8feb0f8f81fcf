// Frame time of the lab's 3D view with its UI, on the Cornell box at about 20k patches in a
// 1600 x 1000 window (vsync off): with the solver idle and with a SolverThread stepping progressive
// refinement (gathering would need a 20k x 20k form-factor matrix). Medians and 99th percentiles.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <thread>

#include "app/bench/BenchTable.h"
#include "app/panels/DisplayPanel.h"
#include "app/solver/SolverThread.h"
#include "app/ui/ImGuiLayer.h"
#include "app/window/Window.h"
#include "radiometry/scene/SceneLibrary.h"
#include "render/GlContext.h"
#include "render/PatchRenderer.h"
#include "render/camera/HomeCamera.h"

namespace radiant::app {
namespace {

constexpr std::size_t kTargetPatches = 20'000;
constexpr int kWidth = 1600;
constexpr int kHeight = 1000;
const glm::vec3 kBackground{0.075f, 0.08f, 0.09f};

double percentile(std::vector<double> samples, double p) {
    std::sort(samples.begin(), samples.end());
    const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(samples.size()))) - 1;
    return samples[std::min(i, samples.size() - 1)];
}

/// The patch area that meshes the scene into about `target` patches (meshing makes patches near the
/// limit, so the count scales as area / limit; two corrections absorb the rounding to whole cells).
double areaForPatchCount(const Scene& scene, std::size_t target) {
    double area = scene.totalArea() / static_cast<double>(target);
    for (int i = 0; i < 2; ++i)
        area *= static_cast<double>(estimatePatchCount(scene, {area})) / static_cast<double>(target);
    return area;
}

/// Where a frame's time goes, in seconds: taking the snapshot and handing it to the renderer; the
/// panels' ImGui frame; the 3D view's draw call (CPU-side: colours, uploads, llvmpipe's vertex
/// stage); ImGui's draw and the swap (llvmpipe rasterises and shades when the frame is flushed).
struct FramePhases {
    std::vector<double> stream, panels, scene, present;
    double processCpuSeconds = 0;  ///< all threads (main, llvmpipe's, the solver's) over the run
};

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point& mark) {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - mark).count();
    mark = now;
    return seconds;
}

/// A minimal lab: the patch renderer fed from the solver thread's snapshots, and the sidebar's
/// Display panel, drawn every frame as the lab does.
class FrameLoop {
public:
    explicit FrameLoop(SolverThread& solver)
        : solver_(solver), window_({kWidth, kHeight, "radiant bench", true, false}), ui_(window_.handle(), 1.0f),
          panel_(settings_, [this] { return renderer_.legend(); }) {}

    /// Draws `count` frames; returns each frame's wall time in seconds (end of one swap to the next).
    std::vector<double> run(int count, std::size_t* uploads = nullptr, FramePhases* phases = nullptr) {
        std::vector<double> seconds;
        const std::uint64_t uploadsBefore = renderer_.radiosityUploads();
        auto last = Clock::now();
        const double cpuBefore = processCpuSeconds();
        for (int i = 0; i < count; ++i) {
            frame(phases);
            const auto now = Clock::now();
            seconds.push_back(std::chrono::duration<double>(now - last).count());
            last = now;
        }
        if (uploads) *uploads = renderer_.radiosityUploads() - uploadsBefore;
        if (phases) phases->processCpuSeconds = processCpuSeconds() - cpuBefore;
        return seconds;
    }

    void frame(FramePhases* phases = nullptr) {
        Clock::time_point mark = Clock::now();
        const auto phase = [&](std::vector<double> FramePhases::*which) {
            const double seconds = since(mark);
            if (phases) (phases->*which).push_back(seconds);
        };
        glfwPollEvents();
        const std::shared_ptr<const Snapshot> snapshot = solver_.snapshot();
        if (snapshot->mesh && snapshot->scene) {
            renderer_.setMesh(*snapshot->scene, *snapshot->mesh, snapshot->meshGeneration);
            renderer_.setRadiosity(snapshot->radiosity, snapshot->generation, snapshot->stats.shooter);
            if (!haveCamera_) {
                camera_ = render::homeCamera(*snapshot->scene);
                haveCamera_ = true;
            }
        }
        phase(&FramePhases::stream);
        ui_.newFrame();
        const float sidebar = 360.0f;
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(sidebar, static_cast<float>(kHeight)));
        ImGui::Begin("Radiant", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
        if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) panel_.draw();
        ImGui::End();
        settings_.colourMode = render::ColourMode::ToneMapped;
        renderer_.setSettings(settings_);
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        const int sidebarPixels = static_cast<int>(sidebar * window_.pixelRatio());
        const render::Viewport view{sidebarPixels, 0, std::max(1, width - sidebarPixels), std::max(1, height)};
        phase(&FramePhases::panels);
        render::beginWindowFrame(width, height, view, kBackground);
        renderer_.draw(camera_, view.aspect());
        phase(&FramePhases::scene);
        render::useWholeWindow(width, height);
        ui_.render();
        window_.swapBuffers();
        phase(&FramePhases::present);
    }

    [[nodiscard]] std::string glRenderer() const { return render::queryGlInfo().renderer; }

private:
    SolverThread& solver_;
    Window window_;
    ImGuiLayer ui_;
    render::DisplaySettings settings_;
    render::PatchRenderer renderer_;
    DisplayPanel panel_;
    render::Camera camera_ = render::cornellCamera();
    bool haveCamera_ = false;
};

std::string ms(double seconds) { return formatNumber(seconds * 1e3); }

} // namespace

BenchTable benchFrames(const BenchOptions& options) {
    BenchTable table;
    table.title = "Frames: Cornell box at ~20k patches, 1600 x 1000 window, vsync off";
    table.columns = {"solver",       "frames",          "median (ms)",      "p99 (ms)",
                     "CPU / frame (ms)", "stream (ms)",  "panels (ms)",     "3D draw (ms)",     "UI + swap (ms)",
                     "radiosity uploads", "solver steps"};
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0') {
        table.notes.push_back("skipped: no display (run under xvfb-run -a -s \"-screen 0 1600x1000x24\")");
        return table;
    }
    const int frames = options.quick ? 60 : 300;

    auto scene = std::make_shared<const Scene>(loadScene("cornell-box").scene);
    MeshingOptions meshing;
    meshing.maxPatchArea = areaForPatchCount(*scene, kTargetPatches);

    SolverThread solver;
    solver.send(command::SetTolerance{1e-12});  // keep stepping for the whole measurement
    solver.send(command::LoadScene{scene, meshing});
    solver.send(command::SetMethod{SolverMethod::Progressive});
    solver.send(command::Step{8});  // a solution to show while idle
    solver.waitUntilIdle();
    FrameLoop loop(solver);
    loop.run(frames / 10);  // warm-up: first uploads, shader compilation, font atlas

    std::size_t idleUploads = 0, runningUploads = 0;
    FramePhases idlePhases, runningPhases;
    const std::size_t stepsBefore = solver.snapshot()->stats.iteration;
    const std::vector<double> idle = loop.run(frames, &idleUploads, &idlePhases);
    const std::size_t stepsIdle = solver.snapshot()->stats.iteration - stepsBefore;
    solver.send(command::Run{});
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the worker is stepping
    const std::size_t runningFrom = solver.snapshot()->stats.iteration;
    const std::vector<double> running = loop.run(frames, &runningUploads, &runningPhases);
    const std::size_t stepsRunning = solver.snapshot()->stats.iteration - runningFrom;
    solver.send(command::Pause{});
    const std::size_t patches = solver.snapshot()->mesh ? solver.snapshot()->mesh->size() : 0;

    const auto row = [&](const char* label, const std::vector<double>& seconds, const FramePhases& phases,
                         std::size_t uploads, std::size_t steps) {
        table.rows.push_back({label, std::to_string(seconds.size()), ms(median(seconds)), ms(percentile(seconds, 0.99)),
                              ms(phases.processCpuSeconds / static_cast<double>(seconds.size())), ms(median(phases.stream)), ms(median(phases.panels)), ms(median(phases.scene)),
                              ms(median(phases.present)), std::to_string(uploads), std::to_string(steps)});
    };
    row("idle", idle, idlePhases, idleUploads, stepsIdle);
    row("progressive running", running, runningPhases, runningUploads, stepsRunning);
    table.notes.push_back(std::to_string(patches) + " patches (max patch area " +
                          formatNumber(meshing.maxPatchArea * 1e4) + " cm^2); GL renderer: " + loop.glRenderer());
    table.notes.push_back("CPU / frame: the process's CPU time over the run (every thread: the window's, llvmpipe's, "
                          "and while running the solver's) per frame; unlike wall times it does not grow when "
                          "other processes share the cores");
    table.notes.push_back("phases are medians of each part of a frame: stream = snapshot to renderer, panels = "
                          "ImGui frame, 3D draw = colours, uploads and llvmpipe's vertex stage, UI + swap = "
                          "ImGui's draw and llvmpipe's rasterisation at the flush");
    table.notes.push_back("running / idle: median " + formatNumber(median(running) / median(idle)) + "x, p99 " +
                          formatNumber(percentile(running, 0.99) / percentile(idle, 0.99)) +
                          "x (target: running p99 < 33 ms and within 1.5x of idle)");
    return table;
}

} // namespace radiant::app
