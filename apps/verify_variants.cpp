// Crossing-variant check for `dualhex verify`: every over/under assignment of the flat,
// concave-edge and concave-corner regions is a valid element and passes its region's torus;
// the classes are 1/3/2 and the best class of each region is the shipped element (F, E, VC).
#include <sstream>

#include "variants_json.hpp"
#include "verify_checks.hpp"

namespace dualhex::app {

void add_variant_checks(CheckRegistry& registry) {
    registry.add({"schemes.crossing-variants",
                  "crossing variants: 2/4/8 assignments valid on their tori, 1/3/2 classes, the best are F, E, VC",
                  [] {
                      const auto report = variants::check_variants(false);
                      CheckOutcome out;
                      out.status = report.ok() ? CheckStatus::kPass : CheckStatus::kFail;
                      std::ostringstream summary;
                      std::size_t valid = 0, total = 0;
                      std::string classes;
                      for (const auto& r : report.regions) {
                          valid += r.valid;
                          total += r.variants.size();
                          classes += (classes.empty() ? "" : "/") + std::to_string(r.classes.size());
                      }
                      summary << valid << "/" << total << " variants valid, classes " << classes
                              << " (expected 1/3/2), best classes "
                              << (report.ok() ? "F, E, VC" : "NOT as expected");
                      out.summary = summary.str();
                      out.details = variants_json(report);
                      std::ostringstream text;
                      variants::print(text, report);
                      out.report = text.str();
                      return out;
                  }});
}

}  // namespace dualhex::app
