// `radiant lesson check FILE...`: reads each lesson file as the lab would play it (every scene
// loaded, every surface and probe point checked) and says how many steps it has, or where it is wrong.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/CommandLine.h"
#include "app/lessons/Lesson.h"

namespace radiant::app {

Subcommand addLessonCommand(CLI::App& root) {
    CLI::App* sub = root.add_subcommand("lesson", "Work with lesson files (docs/lessons.md)");
    sub->require_subcommand(1);
    CLI::App* check = sub->add_subcommand("check", "Check lesson files; exit 2 naming the step and field at fault");
    auto files = std::make_shared<std::vector<std::string>>();
    check->add_option("files", *files, "Lesson JSON files")->required();
    return {sub, [files] {
                for (const std::string& file : *files) {
                    const lesson::Lesson lesson = lesson::readLesson(file);  // RadiantError: exit 2, one line
                    std::size_t actions = 0;
                    for (const lesson::LessonStep& step : lesson.steps) actions += step.actions.size();
                    std::printf("%s: '%s', %zu steps, %zu actions: OK\n", file.c_str(), lesson.title.c_str(),
                                lesson.steps.size(), actions);
                }
                return 0;
            }};
}

} // namespace radiant::app
