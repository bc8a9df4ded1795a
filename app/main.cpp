// blayer: the command line over the library. Parses options (command line over the
// --config case file over defaults), runs one subcommand, and maps the outcome to the
// exit status: 0 success, 1 bad input or failure ("error: ..." on stderr), 2 for
// `check` finding an invalid mesh.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <tbb/global_control.h>

#include "blayer/core/errors.h"
#include "blayer/core/free_heap.h"
#include "commands.h"
#include "huge_pages.h"
#include "parameters.h"

int main(int argc, char** argv) {
  using namespace blayer;
  reexecute_on_huge_pages(argc, argv);  // before anything is allocated or printed
  keep_arrays_in_heap();
  CLI::App app{"blayer: prism boundary-layer meshes for RANS CFD"};
  app.require_subcommand(1);
  app.fallthrough(false);

  CLI::App* normals = app.add_subcommand("normals", "compute point normals of a surface and write them as .vtp");
  CLI::App* extrude = app.add_subcommand("extrude", "grow prism layers on a surface and write a .vtu (the main job)");
  CLI::App* check = app.add_subcommand("check", "check the validity and quality of a volume mesh (.vtu/.vtk)");
  CLI::App* params = app.add_subcommand("params", "print the parameter table as Markdown");
  ParamBinder normals_params(normals, kNormalsCmd);
  ParamBinder extrude_params(extrude, kExtrudeCmd);
  ParamBinder check_params(check, kCheckCmd);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << "\n(run 'blayer --help' or 'blayer COMMAND --help')\n";
    return 1;
  }

  try {
    if (params->parsed()) {
      std::cout << parameter_table_markdown();
      return 0;
    }
    CLI::App* sub = normals->parsed() ? normals : extrude->parsed() ? extrude : check;
    const ParamBinder& binder = sub == normals ? normals_params : sub == extrude ? extrude_params : check_params;
    const ParamValues values = binder.resolve();
    std::unique_ptr<tbb::global_control> threads;
    if (values.get_int("threads") > 0)
      threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      values.get_int("threads"));
    if (sub == normals) return run_normals_command(values);
    if (sub == extrude) return run_extrude_command(values);
    return run_check_command(values);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
  } catch (const IoError& e) {
    std::cerr << "error: " << e.what() << "\n";
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "error: internal failure: " << e.what() << "\n";
  }
  return 1;
}
