// dualhex: builds the CLI11 app, registers the subcommands, maps outcomes to exit codes.
#include <exception>
#include <iostream>

#include "commands.hpp"

int main(int argc, char** argv) {
    using namespace dualhex::app;
    CLI::App app{"dualhex: optimal dual schemes for adaptive-grid hexmeshing"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "dualhex 0.1.0");
    app.footer(
        "Exit codes: 0 success, 1 a check failed, 2 usage error (or output exists without --force),\n"
        "3 input error (error: <file>:<line>: <message>), 4 internal error.");
    register_classify(app);
    register_grid(app);
    register_verify(app);
    register_element(app);
    register_table(app);
    register_install(app);
    register_certify(app);
    register_variants(app);
    register_mesh(app);
    register_audit(app);
    register_atlas(app);

    try {
        app.parse(argc, argv);  // subcommand callbacks run in here
        return kOk;
    } catch (const CLI::ParseError& e) {
        // --help / --version are "errors" with exit code 0 in CLI11; they print to stdout.
        const int code = app.exit(e);
        return code == 0 ? kOk : kUsage;
    } catch (const Exit& e) {
        return e.code;
    } catch (const UsageError& e) {
        std::cerr << "error: " << e.what() << '\n';
        return kUsage;
    } catch (const NotYetAvailable& e) {
        std::cerr << "error: not yet available: " << e.what() << '\n';
        return kInternal;
    }
    catch (const std::exception& e) {
        if (auto msg = input_error_message(e)) {  // dualhex::InputError from grid I/O
            std::cerr << "error: " << *msg << '\n';
            return kInputError;
        }
        std::cerr << "internal error: " << e.what() << '\n';
        return kInternal;
    } catch (...) {
        std::cerr << "internal error: unknown exception\n";
        return kInternal;
    }
}
