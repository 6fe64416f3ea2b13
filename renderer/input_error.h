#pragma once
// InputError (spectra/input_error.h): bad user input; the command line tools exit with code 2 on it.

#include "spectra/input_error.h"
