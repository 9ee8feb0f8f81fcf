#include "app/cli/CommandLine.h"

int main(int argc, char** argv) { return radiant::app::runCommandLine(argc, argv); }
