// dualhex audit FILE: reads someone's hex or polyhedral transition mesh (.vtk, .vtu, .mesh)
// and runs the audit's checks (audit/include/dualhex/audit/audit.hpp), every violation
// located; --certify FILE writes a certificate for the standalone checker.
// Exit: 0 every check passed, 1 a check failed (then no certificate either), 2 usage or
// --certify refused (coordinates not dyadic, beyond 2^19 or coincident), 3 bad input.
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "progress_bar.hpp"

#include "dualhex/audit/audit.hpp"
#include "dualhex/audit/certify.hpp"
#include "dualhex/audit/read_mesh.hpp"
#include "dualhex/checkers/certificate.hpp"

namespace dualhex::app {
namespace {

struct AuditOptionsCli {
    std::string input, mode = "auto", certify;
    std::size_t max_listed = 10;
    bool json = false, force = false, no_progress = false;
};

// The certificate of an audited mesh: polyhedral -> `installation` on its bounding box
// (subdivision, valences, all-hex dual: what `dualhex install --certify` claims); hex ->
// `histogram` on its bounding box too (the checker's always-checked conformity and closed cells,
// plus the counts).
// Returns the refusal, empty if written.
std::string write_audit_certificate(const AuditOptionsCli& opt, const audit::MeshFile& mesh,
                                    const audit::AuditReport& report) {
    if (!report.ok()) return "the audit failed";
    std::string refusal;
    const auto cert = audit::certificate_complex(mesh, refusal);
    if (!cert) return refusal;
    CertificateSpec spec;
    spec.name = "audit";
    spec.kind = report.mode == "polyhedral" ? CertificateKind::Installation : CertificateKind::Histogram;
    spec.domain = CertificateDomain::box(cert->lo, cert->hi);
    spec.comments = {"dualhex audit " + opt.input + " (" + report.mode + " mode), coordinates scaled by 2^" +
                     std::to_string(cert->scale_exponent)};
    std::ofstream out = open_output(opt.certify, opt.force);
    write_certificate(out, cert->complex, spec);
    out.flush();
    if (!out) throw std::runtime_error(opt.certify + ": write failed");
    return {};
}

void run_audit(const AuditOptionsCli& opt) {
    if (!opt.certify.empty()) check_output(opt.certify, opt.force);
    // The bar: reading (size unknown until read), then the audit's own steps.
    ProgressBar bar = ProgressBar::for_stderr(opt.json, opt.no_progress);
    bar.update("audit: read", 0, 0);
    const audit::MeshFile mesh = audit::read_mesh(opt.input);  // InputError -> exit 3
    audit::AuditOptions options;
    if (bar.active())
        options.progress = [&bar](std::string_view stage, std::size_t done, std::size_t total) {
            bar.update("audit: " + std::string(stage), done, total);
        };
    options.max_listed = opt.max_listed;
    options.mode = opt.mode == "hex" ? audit::AuditMode::Hex
                   : opt.mode == "polyhedral" ? audit::AuditMode::Polyhedral
                                              : audit::AuditMode::Auto;
    const audit::AuditReport report = audit::audit_mesh(mesh, options);
    bar.finish("audit: " + with_commas(report.cells) + " cells, " + (report.ok() ? "every check passed" : "a check FAILED"));
    const std::string refusal = opt.certify.empty() ? "" : write_audit_certificate(opt, mesh, report);
    if (opt.json) {
        nlohmann::json j = report.json();
        if (!opt.certify.empty()) j["certificate"] = refusal.empty() ? nlohmann::json(opt.certify) : nlohmann::json(nullptr);
        if (!refusal.empty()) j["certificate_refused"] = refusal;
        print_json(j);
    } else {
        std::fputs(report.text().c_str(), stdout);
        if (!opt.certify.empty() && refusal.empty())
            std::printf("wrote certificate %s (check it with dualhex-proof-checker --file %s)\n", opt.certify.c_str(),
                        opt.certify.c_str());
    }
    if (!refusal.empty()) std::cerr << "error: --certify: not certifying " << opt.input << ": " << refusal << '\n';
    if (!report.ok()) throw Exit{kCheckFailed};
    if (!refusal.empty()) throw Exit{kUsage};
}

}  // namespace

void register_audit(CLI::App& app) {
    auto opt = std::make_shared<AuditOptionsCli>();
    CLI::App* sub = app.add_subcommand(
        "audit",
        "Audit a hex mesh or a polyhedral transition mesh (.vtk legacy ASCII, .vtu, MEDIT .mesh): cell "
        "types, conformity, boundary manifoldness, components, scaled Jacobians, edge valences; for "
        "polyhedra (VTK_POLYHEDRON) the dual conditions (vertex valence 6, octahedral links, edge valence 4, "
        "all-hex dual), every violation located");
    sub->add_option("file", opt->input, "The mesh file")->required();
    sub->add_option("--mode", opt->mode, "auto (default: polyhedral iff a VTK_POLYHEDRON cell), hex or polyhedral")
        ->check(CLI::IsMember({"auto", "hex", "polyhedral"}));
    sub->add_option("--max-listed", opt->max_listed, "Violations listed per check (default 10)");
    sub->add_option("--certify", opt->certify,
                    "Also write a certificate to FILE (coordinates must be dyadic, |x| <= 2^19 once scaled; check "
                    "it with dualhex-proof-checker --file FILE)");
    sub->add_flag("--force", opt->force, "Overwrite the certificate file if it exists");
    add_json_flag(*sub, opt->json);
    add_no_progress_flag(*sub, opt->no_progress);
    sub->callback([opt] { run_audit(*opt); });
}

}  // namespace dualhex::app
