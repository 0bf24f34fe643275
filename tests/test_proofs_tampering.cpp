// The standalone checker under truncated files and tampered manifests (the shipped sets).
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

TEST(ProofsCertificates, TruncationsAndManifestTampering) {
    // a small manifest: the shipped elements and two tori (masks 0 and 1) in a second file
    const fs::path dir = temp_dir("manifest");
    fs::copy(kShipped / "elements.cert", dir / "elements.cert");
    const ElementLibrary library = ElementLibrary::load_default();
    std::string tori;
    for (int mask : {0, 1}) {
        const ConfigurationComplex cc = build_periodic_configuration(static_cast<std::uint8_t>(mask), StrongRule{}, library);
        CertificateSpec spec;
        spec.name = "torus-" + std::to_string(mask);
        spec.kind = CertificateKind::Configuration;
        spec.domain = CertificateDomain::torus(4 * cc.unit);
        spec.covers = {mask};
        tori += certificate_to_string(cc.complex, spec);
    }
    const std::string elements = read(dir / "elements.cert");
    const std::size_t n_elements = split_certificates(elements).size();
    std::vector<ManifestEntry> entries{
        write_certificate_file(dir, "elements.cert", elements, n_elements, CertificateKind::Element),
        write_certificate_file(dir, "tori.cert", tori, 2, CertificateKind::Configuration)};
    write(dir / "manifest", manifest_to_string(entries, 2));
    ASSERT_EQ(run_checker((dir / "manifest").string()).code, 0);
    std::size_t tried = 0, rejected = 0;
    auto expect_reject = [&](const std::string& what) {
        const CheckerRun r = run_checker((dir / "manifest").string());
        ++tried;
        rejected += r.code == 1;
        EXPECT_EQ(r.code, 1) << what << "\n" << r.out;
        EXPECT_EQ(r.out.find("VERIFIED"), std::string::npos) << what;
    };
    const std::string manifest = read(dir / "manifest");
    // truncate the file (manifest hash updated, so only the truncation can be caught)
    for (int k = 1; k < 40; ++k) {
        const std::string cut = elements.substr(0, elements.size() * k / 40);
        std::string m = manifest;
        m.replace(m.find(fnv1a64_hex(elements)), 16, fnv1a64_hex(cut));
        write(dir / "elements.cert", cut);
        write(dir / "manifest", m);
        expect_reject("truncated at " + std::to_string(cut.size()));
    }
    write(dir / "elements.cert", elements);
    // wrong hash: every hex digit of every file's hash
    std::size_t at = 0;
    while ((at = manifest.find("fnv1a64 ", at)) != std::string::npos) {
        at += 8;
        for (int d = 0; d < 16; ++d) {
            std::string m = manifest;
            m[at + d] = m[at + d] == '0' ? '1' : '0';
            write(dir / "manifest", m);
            expect_reject("hash digit");
        }
    }
    // wrong counts: total, covers, per-file count; a file dropped
    const std::string counted = "elements.cert " + std::to_string(n_elements);
    for (const char* from_c : {"total ", "covers 2", counted.c_str(), "file tori.cert"}) {
        const std::string from = from_c;
        std::string m = manifest;
        const auto p = m.find(from);
        ASSERT_NE(p, std::string::npos) << from;
        if (from.rfind("file ", 0) == 0) m.erase(p, m.find('\n', p) + 1 - p);
        else if (from == "total ") m.insert(p + from.size(), "1");
        else m.replace(p, from.size(), from.substr(0, from.size() - 1) + "7");
        write(dir / "manifest", m);
        expect_reject(from);
    }
    write(dir / "manifest", manifest);
    EXPECT_EQ(run_checker((dir / "manifest").string()).code, 0);
    std::cout << "[ tampering ] tried " << tried << ", rejected " << rejected << '\n';
    fs::remove_all(dir);
}

// Tampering with a copy of a shipped set: its manifest, and covers lines inside a file (the
// file's hash updated, so only the covers check can catch it). Returns {tried, rejected}.
std::pair<std::size_t, std::size_t> tamper_with_set(const std::string& set) {
    const fs::path dir = temp_dir("tamper-" + set);
    fs::copy(kShipped / set, dir, fs::copy_options::recursive);
    const std::string manifest = read(dir / "manifest");
    std::size_t tried = 0, rejected = 0;
    auto expect_reject = [&](const std::string& what, const std::string& m) {
        write(dir / "manifest", m);
        const CheckerRun r = run_checker((dir / "manifest").string());
        ++tried;
        rejected += r.code == 1 && r.out.find("VERIFIED") == std::string::npos;
        EXPECT_EQ(r.code, 1) << set << ": " << what << "\n" << r.out;
    };
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string m = manifest;
        const auto p = m.find(from);
        EXPECT_NE(p, std::string::npos) << from;
        return p == std::string::npos ? m : m.replace(p, from.size(), to);
    };
    const long covers = std::stol(manifest.substr(manifest.find("\ncovers ") + 8));
    expect_reject("covers N-1", replaced("covers " + std::to_string(covers), "covers " + std::to_string(covers - 1)));
    expect_reject("covers N+1", replaced("covers " + std::to_string(covers), "covers " + std::to_string(covers + 1)));
    expect_reject("total + 1", replaced("total ", "total 1"));
    const auto last = manifest.rfind("\nfile ") + 1;
    const std::string file_line = manifest.substr(last);  // the last line
    expect_reject("file dropped", replaced(file_line, ""));
    // the last covers line of the last file: a label dropped, another's label, its own label twice
    std::istringstream ls(file_line);
    std::string word, file, count, kind, algo, hash;
    ls >> word >> file >> count >> kind >> algo >> hash;
    const std::string body = read(dir / file);
    const auto at = body.rfind("\ncovers ") + 1;
    const std::string line = body.substr(at, body.find('\n', at) - at);
    const std::string first = line.substr(7, line.find(' ', 7) - 7);
    const std::string other = std::to_string(std::stol(first) == 0 ? covers - 1 : 0);
    for (const std::string& edited : {line.substr(0, line.rfind(' ')), line + " " + other, line + " " + first}) {
        if (edited == "covers") continue;  // a one-label line: dropping its label is "covers N+1"
        const std::string tampered = std::string(body).replace(at, line.size(), edited);
        write(dir / file, tampered);
        expect_reject("covers line '" + edited.substr(0, 40) + "'", replaced(hash, fnv1a64_hex(tampered)));
    }
    write(dir / file, body);
    for (std::size_t h = 0; (h = manifest.find("fnv1a64 ", h)) != std::string::npos;) {  // a digit of each hash
        h += 8;
        std::string m = manifest;
        m[h] = m[h] == '0' ? '1' : '0';
        expect_reject("hash digit", m);
    }
    write(dir / "manifest", manifest);
    EXPECT_EQ(run_checker((dir / "manifest").string()).code, 0) << "the untampered copy must verify";
    fs::remove_all(dir);
    return {tried, rejected};
}

TEST(ProofsCertificates, WeakAndVariantManifestTampering) {
    for (const char* set : {"weak", "variants", "windows", "boundary", "weak_spread", "weak_stars", "weak_corner_stars", "weak_root_stars"}) {
        const auto [tried, rejected] = tamper_with_set(set);
        std::cout << "[ tampering ] " << set << ": tried " << tried << ", rejected " << rejected << '\n';
        EXPECT_EQ(rejected, tried);
        EXPECT_GE(tried, std::string(set) == "weak_spread" ? 7u : 8u);  // one file, one label per certificate
    }
}

}  // namespace
}  // namespace dualhex
