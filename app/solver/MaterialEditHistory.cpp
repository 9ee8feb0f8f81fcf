#include "app/solver/MaterialEditHistory.h"

#include <utility>

namespace radiant::app {

void MaterialEditHistory::follow(const Scene& shown, const void* sceneKey) {
    if (sceneKey == sceneKey_ && shown.name == sceneName_) return;
    sceneKey_ = sceneKey;
    sceneName_ = shown.name;
    done_.clear();
    undone_.clear();
    sent_.clear();
    lastWasEdit_ = false;
}

MaterialValues MaterialEditHistory::current(const Scene& shown, std::size_t surface) const {
    if (const auto sent = sent_.find(surface); sent != sent_.end()) return sent->second;
    const Material& material = shown.materials.at(shown.surfaces.at(surface).material);
    return {material.reflectance, material.exitance.value()};
}

void MaterialEditHistory::recordEdit(const Scene& shown, std::size_t surface, const MaterialValues& after,
                                     bool continuesEdit) {
    // A continuing gesture extends its own entry: the drag is undone in one step, back to where it began.
    if (continuesEdit && lastWasEdit_ && !done_.empty() && done_.back().changes.size() == 1 &&
        done_.back().changes.front().surface == surface) {
        done_.back().changes.front().after = after;
    } else {
        const MaterialValues before = current(shown, surface);
        if (before == after) return;  // nothing changes: nothing to undo
        done_.push_back({{{surface, shown.surfaces.at(surface).name, before, after}}, false});
        if (done_.size() > kMaxEntries) done_.erase(done_.begin());
    }
    undone_.clear();
    sent_[surface] = after;
    lastWasEdit_ = true;
}

void MaterialEditHistory::recordReset(const Scene& shown) {
    Entry entry{{}, true};
    // Only the surfaces edited here can differ from the scene's own materials (lessons and sessions
    // edit through here too).
    for (const auto& [surface, values] : sent_)
        if (surface < shown.surfaces.size())
            entry.changes.push_back({surface, shown.surfaces[surface].name, values, values});
    sent_.clear();  // the scene's own values now, which the next snapshot shows
    lastWasEdit_ = false;
    if (entry.changes.empty()) return;
    done_.push_back(std::move(entry));
    if (done_.size() > kMaxEntries) done_.erase(done_.begin());
    undone_.clear();
}

std::vector<SolverCommand> MaterialEditHistory::undo() {
    std::vector<SolverCommand> commands;
    if (done_.empty()) return commands;
    Entry entry = std::move(done_.back());
    done_.pop_back();
    for (const Change& change : entry.changes) {
        commands.emplace_back(command::SetMaterial{change.surface, change.before.reflectance,
                                                   ExitanceRgb(change.before.exitanceW_m2), false});
        sent_[change.surface] = change.before;
    }
    undone_.push_back(std::move(entry));
    lastWasEdit_ = false;
    return commands;
}

std::vector<SolverCommand> MaterialEditHistory::redo() {
    std::vector<SolverCommand> commands;
    if (undone_.empty()) return commands;
    Entry entry = std::move(undone_.back());
    undone_.pop_back();
    if (entry.reset) {
        commands.emplace_back(command::ResetMaterials{});
        sent_.clear();
    } else {
        for (const Change& change : entry.changes) {
            commands.emplace_back(command::SetMaterial{change.surface, change.after.reflectance,
                                                       ExitanceRgb(change.after.exitanceW_m2), false});
            sent_[change.surface] = change.after;
        }
    }
    done_.push_back(std::move(entry));
    lastWasEdit_ = false;
    return commands;
}

std::string MaterialEditHistory::label(const Entry& entry) {
    if (entry.reset) return "Reset materials (" + std::to_string(entry.changes.size()) + " surfaces)";
    if (entry.changes.size() == 1) return "the edit of " + entry.changes.front().name;
    return "the edits of " + std::to_string(entry.changes.size()) + " surfaces";
}

std::string MaterialEditHistory::undoLabel() const { return done_.empty() ? "" : label(done_.back()); }
std::string MaterialEditHistory::redoLabel() const { return undone_.empty() ? "" : label(undone_.back()); }

} // namespace radiant::app
