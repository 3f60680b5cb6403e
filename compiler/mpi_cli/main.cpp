// oasisc-mpi: the compiler's work spread over the ranks of an MPI job, started by mpirun.
//   quotient  the coarsest bisimulation of one large .aut model, its states spread over the
//             ranks' memory (docs/bisimulation.md, "Past one machine")
//   compile   a catalog whose contexts are dealt out to the ranks

#include <sstream>

#include "mpi_cli/commands.hpp"

int main(int argc, char** argv) {
  using namespace oasis;
  distributed::Communicator communicator(argc, argv);
  CLI::App app(
      "oasisc-mpi: oasisc's bisimulation and compile spread over the ranks of an MPI job\n"
      "(mpirun -np P oasisc-mpi COMMAND ...). Every rank runs the same command; rank 0 writes\n"
      "the output and the report. 'oasisc-mpi COMMAND --help' explains each.",
      "oasisc-mpi");
  app.require_subcommand(1);
  const mpi_cli::CommandRunner quotient = mpi_cli::add_quotient_command(app, communicator);
  const mpi_cli::CommandRunner compile = mpi_cli::add_compile_command(app, communicator);
  std::ostringstream discarded;  // only rank 0 speaks about the command line
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return communicator.is_root() ? app.exit(error) : app.exit(error, discarded, discarded);
  }
  return app.got_subcommand("quotient") ? quotient() : compile();
}
