// dualhex classify: the classes of the 256 application-point configurations.
#include <cstdio>
#include <iostream>
#include <memory>

#include "classification.hpp"
#include "commands.hpp"

namespace dualhex::app {
namespace {

struct ClassifyOptions {
    bool json = false;
};

std::string mask_bits(int mask) {
    std::string s(8, '0');
    for (int b = 0; b < 8; ++b)
        if (mask & (1 << b)) s[7 - b] = '1';
    return s;
}

void run_classify(const ClassifyOptions& opt) {
    const Classification c = compute_classification();
    const bool matches = c.classes_full_group == kPaperClassesFullGroup &&
                         c.nontrivial_classes == kPaperNontrivialClasses &&
                         c.classes_rotations == kExpectedClassesRotations;
    if (opt.json) {
        nlohmann::json classes = nlohmann::json::array();
        for (const auto& row : c.classes)
            classes.push_back(
                {{"representative", row.representative}, {"size", row.size}, {"fine_octants", row.fine_octants}});
        print_json({{"configurations", c.configurations},
                    {"classes_full_group", c.classes_full_group},
                    {"classes_rotations", c.classes_rotations},
                    {"nontrivial_classes", c.nontrivial_classes},
                    {"paper",
                     {{"classes_full_group", kPaperClassesFullGroup},
                      {"nontrivial_classes", kPaperNontrivialClasses},
                      {"classes_rotations_expected", kExpectedClassesRotations}}},
                    {"matches_paper", matches},
                    {"classes", classes}});
    } else {
        std::printf("%-4s %-10s %-8s %5s %13s\n", "#", "mask", "bits", "size", "fine_octants");
        int i = 0;
        for (const auto& row : c.classes)
            std::printf("%-4d %-10d %-8s %5d %13d\n", i++, row.representative, mask_bits(row.representative).c_str(),
                        row.size, row.fine_octants);
        std::printf("\n%d configurations\n", c.configurations);
        std::printf("classes under the 48 symmetries: %d (paper: %d)\n", c.classes_full_group,
                    kPaperClassesFullGroup);
        std::printf("non-trivial classes:             %d (paper: %d)\n", c.nontrivial_classes,
                    kPaperNontrivialClasses);
        std::printf("classes under the 24 rotations:  %d (expected: %d)\n", c.classes_rotations,
                    kExpectedClassesRotations);
        std::printf("%s\n", matches ? "matches the paper" : "DOES NOT match the paper");
    }
    if (!matches) throw Exit{kCheckFailed};
}

}  // namespace

void register_classify(CLI::App& app) {
    auto opt = std::make_shared<ClassifyOptions>();
    auto* sub = app.add_subcommand(
        "classify", "Classify the 256 octant configurations around an application point under the cube symmetries");
    add_json_flag(*sub, opt->json);
    sub->callback([opt] { run_classify(*opt); });
}

}  // namespace dualhex::app
