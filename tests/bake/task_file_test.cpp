// Farm task files (bake/farm/task_file.h): arrays read back by copy and in place are the
// values written, at any alignment the fields before them leave, and a count that runs
// past the section is refused naming the file, the section and the field; sections read
// from the mapped file outlive the TaskFile; files that are no task file are refused.
#include "bake/farm/task_file.h"
#include "schema/error.h"

#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace opal {
namespace {

TEST(TaskFile, ArraysReadInPlaceAreTheValuesWrittenAtAnyAlignment) {
    const test::ScratchDir dir;
    const std::vector<std::uint32_t> odd = {7, 8, 9};  // leaves the next array 4 bytes off 8
    const std::vector<std::uint64_t> wide = {1ull << 40, 3, 0xffffffffffffffffull};
    const std::vector<float> values = {0.5f, -2.25f, 1e-30f, 3.0f};
    SectionWriter w;
    w.array(odd);
    w.array(wide);
    w.array(values);
    writeTaskFile(dir / "a.task", std::vector<std::string>{w.take()});

    SectionReader r = TaskFile(dir / "a.task").section(0);
    EXPECT_EQ(r.array<std::uint32_t>("odd"), odd);
    const SectionArray<std::uint64_t> w2 = r.view<std::uint64_t>("wide");
    const SectionArray<float> v2 = r.view<float>("values");
    r.expectEnd();
    ASSERT_EQ(w2.size(), wide.size());
    for (std::size_t i = 0; i < wide.size(); ++i) EXPECT_EQ(w2[i], wide[i]);
    ASSERT_EQ(v2.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(v2[i], values[i]);
}

TEST(TaskFile, AnArrayLongerThanItsSectionIsRefusedByName) {
    const test::ScratchDir dir;
    SectionWriter w;
    w.u64(1000);  // a count with nothing after it
    w.u32(5);
    writeTaskFile(dir / "a.task", std::vector<std::string>{w.take()});
    SectionReader r = TaskFile(dir / "a.task").section(0);
    try {
        (void)r.view<float>("values");
        FAIL() << "an array past the section was read";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("a.task: section 0"), std::string::npos) << message;
        EXPECT_NE(message.find("values holds 1000 values"), std::string::npos) << message;
    }
}

TEST(TaskFile, ASectionStaysReadableAfterItsFileObjectIsGone) {
    const test::ScratchDir dir;
    SectionWriter w;
    w.array(std::vector<float>{1.5f, 2.5f});
    writeTaskFile(dir / "a.task", std::vector<std::string>{w.take()});
    std::optional<SectionReader> r;
    {
        const TaskFile file(dir / "a.task");
        r.emplace(file.section(0));
    }
    const SectionArray<float> v = r->view<float>("values");  // the mapping lives with the reader
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v[1], 2.5f);
}

TEST(TaskFile, AnEmptyFileAShortHeaderOrAFolderIsRefusedNamingIt) {
    const test::ScratchDir dir;
    writeTaskFile(dir / "whole.task", std::vector<std::string>{"a section"});
    const std::string bytes = test::readBytes(dir / "whole.task");
    test::writeText(dir / "empty.task", "");
    test::writeText(dir / "short.task", bytes.substr(0, 20));  // magic, version, count; no sizes
    std::filesystem::create_directories(dir / "folder.task");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"empty.task", "not a farm task file"},
        {"short.task", "the header is cut short"},
        {"folder.task", "not a regular file"},
        {"missing.task", "cannot read the farm task file"}};
    for (const auto& [name, problem] : cases) {
        try {
            (void)TaskFile(dir / name);
            ADD_FAILURE() << name << " was opened";
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find((dir / name).string() + ": "), std::string::npos) << message;
            EXPECT_NE(message.find(problem), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace opal
