#pragma once
// One section of the lab's sidebar (Info, Scene, Solver, ...): each panel is its own class and file,
// and draws its contents with ImGui when its header is open.
namespace radiant::app {

class Panel {
public:
    virtual ~Panel() = default;
    [[nodiscard]] virtual const char* title() const = 0;
    [[nodiscard]] virtual bool openByDefault() const { return true; }
    /// Called once every frame, shown or not, before drawing (poll background work here).
    virtual void update() {}
    /// True while the panel changes without input (background work in flight, a run animating):
    /// the lab keeps drawing frames instead of waiting for events.
    [[nodiscard]] virtual bool busy() const { return false; }
    /// True while the panel shows work that refines slowly and posts no event (the path tracer):
    /// the idle lab then wakes twice a second to show it, else seldom (Lab::frameWhenNeeded).
    [[nodiscard]] virtual bool refreshesUnprompted() const { return false; }
    /// Called inside the sidebar window, between the panel's header and the next one.
    virtual void draw() = 0;
    /// Opens every section inside the panel at its next draw (the sidebar's "expand all").
    virtual void expandAll() {}
};

} // namespace radiant::app
