#include "app/solver/ConvergenceRecord.h"

#include "app/solver/MethodLabel.h"

namespace radiant::app {

std::vector<SegmentView> ConvergenceRecord::segments(const SolveHistory& currentSteps) const {
    std::vector<SegmentView> views;
    if (finished_)
        for (const HistorySegment& segment : *finished_) views.push_back({&segment.info, &segment.steps});
    if (!currentSteps.empty()) views.push_back({&current_, &currentSteps});
    return views;
}

void ConvergenceRecorder::finishCurrent() {
    if (steps_.size() == 0) return;
    // A new list, so that records already handed out keep theirs.
    auto finished = finished_ ? std::make_shared<std::vector<HistorySegment>>(*finished_)
                              : std::make_shared<std::vector<HistorySegment>>();
    finished->push_back({current_, steps_.snapshot()});
    finished_ = std::move(finished);
    steps_.clear();
}

std::string ConvergenceRecorder::restartLabel(SolverMethod method) const {
    return std::string(methodLabel(method)) + (editsSinceLoad_ > 0 ? " (edited materials)" : "");
}

void ConvergenceRecorder::restart(SolverMethod method) {
    finishCurrent();
    if (finished_) {
        auto kept = std::make_shared<std::vector<HistorySegment>>();
        for (const HistorySegment& segment : *finished_)
            if (segment.info.method != method) kept->push_back(segment);
        finished_ = std::move(kept);
    }
    current_ = {method, 0, restartLabel(method)};
}

void ConvergenceRecorder::materialEdited(const std::string& surfaceName, bool continues) {
    if (continues && current_.index > 0) {
        // The steps since the gesture began solved for a value it has since left (a digit typed,
        // a slider moved on): the segment shows the re-solve from its latest value only.
        steps_.clear();
        return;
    }
    ++editsSinceLoad_;
    if (steps_.size() == 0) {
        // Nothing solved since the last cut: the coming steps start from the same solution.
        current_.label = current_.index == 0
                             ? restartLabel(current_.method)
                             : std::string(methodLabel(current_.method)) + ", edit " +
                                   std::to_string(current_.index) + ": " + surfaceName;
        return;
    }
    finishCurrent();
    ++current_.index;
    current_.label = std::string(methodLabel(current_.method)) + ", edit " + std::to_string(current_.index) + ": " +
                     surfaceName;
}

void ConvergenceRecorder::materialsRestored(SolverMethod method) {
    editsSinceLoad_ = 0;
    restart(method);
}

void ConvergenceRecorder::clear(SolverMethod method) {
    finished_.reset();
    steps_.clear();
    editsSinceLoad_ = 0;
    current_ = {method, 0, restartLabel(method)};
}

} // namespace radiant::app
