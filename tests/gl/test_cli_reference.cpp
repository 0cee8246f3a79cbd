// docs/cli.md is the CLI reference: every block in it must be what toyhost's --help prints today
// (refresh with scripts/update-cli-doc.sh, never automatically).
#include "GlTestSupport.h"

#include <fstream>
#include <sstream>

namespace toyhost::testing {
namespace {

// The ```text blocks of docs/cli.md, keyed by the "## toyhost ..." heading above each.
std::vector<std::pair<std::string, std::string>> documentedHelp() {
    std::ifstream file(sourceDir() / "docs/cli.md");
    std::vector<std::pair<std::string, std::string>> blocks;
    std::string line, heading, block;
    bool inBlock = false;
    while (std::getline(file, line)) {
        if (inBlock) {
            if (line == "```") {
                blocks.emplace_back(heading, block);
                inBlock = false;
            } else {
                block += line + "\n";
            }
        } else if (line.rfind("## ", 0) == 0) {
            heading = line.substr(3);
        } else if (line == "```text") {
            inBlock = true;
            block.clear();
        }
    }
    return blocks;
}

TEST(CliReference, DocsCliMdIsTheHelpOfEveryCommand) {
    const auto blocks = documentedHelp();
    std::vector<std::string> headings;
    for (const auto& [heading, text] : blocks) {
        headings.push_back(heading);
        const std::string command = heading.substr(std::string("toyhost").size());
        const CommandResult help = runToyhost(command + " --help");
        EXPECT_EQ(help.exitCode, 0) << heading;
        EXPECT_EQ(help.output, text) << "docs/cli.md is out of date for `" << heading
                                     << " --help`: run scripts/update-cli-doc.sh";
    }
    EXPECT_EQ(headings, (std::vector<std::string>{"toyhost", "toyhost run", "toyhost import", "toyhost inspect",
                                                 "toyhost new", "toyhost media", "toyhost sound", "toyhost compare",
                                                 "toyhost farm", "toyhost farm plan", "toyhost farm status",
                                                 "toyhost farm join"}));
}

}  // namespace
}  // namespace toyhost::testing
