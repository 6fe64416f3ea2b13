#include "tools/cli/program.h"

#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

#include "materials/graph/graph_error.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

const char* current_program = "ochre";

int report(const char* kind, const char* what, int code) {
  std::cerr << current_program << ": " << kind << ": " << message_excerpt(what) << "\n";
  return code;
}

}  // namespace

const char* program_name() {
  return current_program;
}

int report_current_exception() {
  try {
    throw;
  } catch (const InputError& e) {
    return report("error", e.what(), kExitBadInput);
  } catch (const GraphError& e) {
    return report("error", e.what(), kExitBadInput);
  } catch (const ImageError& e) {
    return report("error", e.what(), kExitBadInput);
  } catch (const std::filesystem::filesystem_error& e) {  // names the path: one the user gave, or its folder
    return report("error", e.what(), kExitBadInput);
  } catch (const std::bad_alloc&) {
    return report("internal error", "out of memory", kExitInternalError);
  } catch (const std::exception& e) {
    return report("internal error", e.what(), kExitInternalError);
  } catch (...) {
    return report("internal error", "unknown exception", kExitInternalError);
  }
}

int run_program(const char* program, const std::function<int()>& body) {
  current_program = program;
  try {
    return body();
  } catch (...) {
    return report_current_exception();
  }
}

}  // namespace ochre
