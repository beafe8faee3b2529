#pragma once
// Helpers the spectral tests share: a scratch folder per test and a file writer.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace gonio::spectral::test {

// A fresh folder under the system's temporary folder, named after the running test.
inline std::filesystem::path ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("gonio_spectral_" + std::string(info->test_suite_name()) + "_" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string WriteFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

}  // namespace gonio::spectral::test
