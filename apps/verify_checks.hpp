#pragma once
// The registry of named checks that `dualhex verify` runs. Each area adds its checks in
// its own add_*_checks function (verify_checks.cpp for now; later layers such as
// checkers/ and schemes/ add theirs the same way and get listed in default_checks()).
#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace dualhex::app {

enum class CheckStatus { kPass, kFail, kSkip };

struct CheckOutcome {
    CheckStatus status = CheckStatus::kFail;
    std::string summary;                             ///< one line for the table
    nlohmann::json details = nlohmann::json::object();  ///< machine-readable numbers
    std::string report;  ///< optional multi-line detail, printed under the table row (text mode)
};

struct Check {
    std::string name;         ///< stable identifier, e.g. "symmetry.group-order"
    std::string description;  ///< what is checked, one line
    std::function<CheckOutcome()> run;  ///< may throw: reported as FAIL with the message
    /// A long exhaustive run: only when --only gives its exact name (listed, not in the default run).
    bool on_request = false;
};

/// Whether a run with `only` (empty: the default run) runs c: without --only every check but
/// those on request; with it, those whose name contains one of the texts, and those on
/// request whose name is one of them (so `--only proofs` starts no long run).
[[nodiscard]] bool is_selected(const Check& c, const std::vector<std::string>& only);

class CheckRegistry {
public:
    void add(Check check) { checks_.push_back(std::move(check)); }
    [[nodiscard]] const std::vector<Check>& checks() const { return checks_; }

private:
    std::vector<Check> checks_;
};

void add_symmetry_checks(CheckRegistry& registry);
void add_configuration_checks(CheckRegistry& registry);
void add_grid_checks(CheckRegistry& registry);
/// A face-size histogram as the JSON columns {"F3": n, ..., "F7": n} of the paper's table.
nlohmann::json face_size_columns(const std::map<int, std::size_t>& histogram);
void add_scheme_checks(CheckRegistry& registry);  // verify_schemes.cpp
void add_variant_checks(CheckRegistry& registry);  // verify_variants.cpp
void add_weak_checks(CheckRegistry& registry);    // verify_weak.cpp
void add_compositional_checks(CheckRegistry& registry);  // verify_compositional.cpp
void add_weak_root_checks(CheckRegistry& registry);      // verify_weak_root.cpp
void add_weak_star_checks(CheckRegistry& registry);      // verify_weak_stars.cpp

/// Every check that exists so far, in run order.
CheckRegistry default_checks();

const char* to_string(CheckStatus s);

}  // namespace dualhex::app
