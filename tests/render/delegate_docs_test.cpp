// delegate/DELEGATE.md copies two tables of the code for readers: the AOVs (hd/aov.h) and
// the render settings (render_settings.cpp). These tests hold the copies to the code.
#include "delegate/render_delegate.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace opal {
namespace {

// The rows of the markdown table under `heading`: cells without their backquotes.
std::vector<std::vector<std::string>> tableRows(const std::string& heading) {
    std::ifstream in(std::string(OPAL_SOURCE_DIR) + "/delegate/DELEGATE.md");
    std::string line;
    while (std::getline(in, line) && line != heading) {
    }
    std::vector<std::vector<std::string>> rows;
    bool inTable = false;
    while (std::getline(in, line) && !line.starts_with("## ")) {
        if (!line.starts_with("| `")) {
            if (inTable) break;
            continue;
        }
        inTable = true;
        std::vector<std::string> cells;
        std::stringstream cellsOf(line.substr(1));
        std::string cell;
        while (std::getline(cellsOf, cell, '|')) {
            std::string clean;
            for (char c : cell)
                if (c != '`') clean += c;
            const auto first = clean.find_first_not_of(' '), last = clean.find_last_not_of(' ');
            cells.push_back(first == std::string::npos ? "" : clean.substr(first, last - first + 1));
        }
        rows.push_back(cells);
    }
    return rows;
}

TEST(DelegateDocs, TheAovTableIsHdAovsTable) {
    const auto rows = tableRows("## AOVs");
    ASSERT_EQ(rows.size(), hd::aovTable().size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const hd::AovDescriptor& aov = hd::aovTable()[i];
        EXPECT_EQ(rows[i][0], aov.name);
        std::string channels;
        for (std::string_view c : aov.channels) {
            if (!channels.empty()) channels.push_back(' ');
            channels.append(c);
        }
        EXPECT_EQ(rows[i][1], channels) << aov.name;
        EXPECT_EQ(rows[i][2], aov.exrLayer.empty() ? "default" : std::string(aov.exrLayer)) << aov.name;
        EXPECT_EQ(rows[i][3], aov.format == hd::AovFormat::Float16 ? "float16" : "float32") << aov.name;
        EXPECT_EQ(rows[i][4], aov.sampling == hd::AovSampling::Filtered ? "filtered" : "nearest") << aov.name;
    }
}

std::string valueText(const hd::Value& v) {
    if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
    if (const int* i = std::get_if<int>(&v)) return std::to_string(*i);
    if (const std::string* s = std::get_if<std::string>(&v)) {
        std::string quoted = "\"";
        quoted.append(*s).push_back('"');
        return quoted;
    }
    return "?";
}

TEST(DelegateDocs, TheSettingsTableIsTheDescriptors) {
    const auto rows = tableRows("## Render settings");
    const auto descriptors = RenderSettings::descriptors();
    ASSERT_EQ(rows.size(), descriptors.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const hd::RenderSettingDescriptor& d = descriptors[i];
        EXPECT_EQ(rows[i][0], d.key);
        EXPECT_EQ(rows[i][1], valueTypeName(d.defaultValue)) << d.key;
        EXPECT_EQ(rows[i][2], valueText(d.defaultValue)) << d.key;
        if (d.min) {
            EXPECT_EQ(rows[i][3], std::to_string(int(*d.min)) + ".." + std::to_string(int(*d.max))) << d.key;
        }
    }
}

}  // namespace
}  // namespace opal
