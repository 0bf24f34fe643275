// The shipped certificates are current: regenerated with the producer, byte for byte.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include "dualhex/checkers/certificate.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/schemes/element_check.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/validation.hpp"
#include "test_proofs_fixture.hpp"

namespace dualhex {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------------ freshness
TEST(ProofsCertificates, ShippedCertificatesAreCurrent) {
    // Regenerate from the library and rules as they are now; every manifest (hash of every
    // certificate file) must be byte-identical to the shipped one. If this fails, the
    // elements or a rule changed: run `dualhex certify --out proofs/certificates --force`.
    const fs::path dir = temp_dir("fresh");
    const CertifyResult result = certify_library(ElementLibrary::load_default(), dir);
    ASSERT_EQ(result.sets.size(), 9u);
    EXPECT_EQ(result.sets[0].covers, 256);
    EXPECT_EQ(result.sets[1].covers, 487);
    EXPECT_EQ(result.sets[2].covers, 14);
    EXPECT_EQ(result.sets[3].covers, 36635);  // the compositional windows
    EXPECT_EQ(result.sets[4].covers, 3368);   // the root-boundary half windows, coarse + mirror
    EXPECT_EQ(result.sets[5].covers, 8);      // the four-level grids, one per corner
    EXPECT_EQ(result.sets[6].covers, 163417); // the weak stars, W10's count (proofs/README.md)
    EXPECT_EQ(result.sets[7].covers, 2736);   // the odd corner pair's quadrant tuples (W11), a witness star each
    EXPECT_EQ(result.sets[8].covers, 7048);   // the weak root-surface stars, coarse + mirror (W13)
    for (const CertificateSet& set : result.sets) {
        const fs::path shipped = kShipped / fs::relative(set.directory, dir);
        EXPECT_EQ(read(set.directory / "manifest"), read(shipped / "manifest"))
            << shipped << " is stale: regenerate with `dualhex certify --out proofs/certificates --force`";
        for (const ManifestEntry& e : set.files) EXPECT_EQ(read(set.directory / e.file), read(shipped / e.file)) << e.file;
        const CheckerRun r = run_checker((set.directory / "manifest").string());
        EXPECT_EQ(r.code, 0) << r.out;
        std::cout << "[ certified ] " << shipped << ": " << set.certificates << " certificates, " << set.bytes
                  << " bytes, covers " << set.covers << '\n';
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace dualhex
