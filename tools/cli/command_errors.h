#pragma once
// How the commands of `ochre` report an exception (docs/cli.md, exit codes): bad input (InputError, a
// material graph error, an image that cannot be read or written) prints "ochre: error: ..." and gives
// exit code 2; anything else is an internal error, exit code 1.

namespace ochre {

// Call inside a catch block: prints the exception being handled and returns the exit code.
int report_current_exception();

}  // namespace ochre
