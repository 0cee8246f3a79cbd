// TestFolder: a fresh, empty folder for one test (unique per process, suite, test and instance),
// removed when the test ends, with small helpers to write and list files. No GL needed.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace toyhost::testing {

struct TestFolder {
    std::filesystem::path path;

    TestFolder() {
        static int counter = 0;
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        path = std::filesystem::temp_directory_path() /
               ("toyhost_" + std::to_string(::getpid()) + "_" + test->test_suite_name() + "_" + test->name() + "_" +
                std::to_string(counter++));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TestFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TestFolder(const TestFolder&) = delete;
    TestFolder& operator=(const TestFolder&) = delete;

    // Writes `text` to path/relative (folders created) and returns the file's path.
    std::filesystem::path write(const std::filesystem::path& relative, const std::string& text) const {
        const std::filesystem::path file = (path / relative).lexically_normal();
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    // Every file left in the folder, recursively (to catch .partial leftovers).
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
            if (!entry.is_directory()) names.push_back(entry.path().filename().string());
        return names;
    }
};

}  // namespace toyhost::testing
