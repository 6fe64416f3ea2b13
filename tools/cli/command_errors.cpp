#include "tools/cli/command_errors.h"

#include <exception>
#include <iostream>

#include "materials/graph/graph_error.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"

namespace ochre {

int report_current_exception() {
  try {
    throw;
  } catch (const InputError& e) {
    std::cerr << "ochre: error: " << e.what() << "\n";
    return 2;
  } catch (const GraphError& e) {
    std::cerr << "ochre: error: " << e.what() << "\n";
    return 2;
  } catch (const ImageError& e) {
    std::cerr << "ochre: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ochre: internal error: " << e.what() << "\n";
    return 1;
  } catch (...) {
    std::cerr << "ochre: internal error: unknown exception\n";
    return 1;
  }
}

}  // namespace ochre
