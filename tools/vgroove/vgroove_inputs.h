#pragma once
// Command-line values of ochre-vgroove (docs/tools.md), parsed and checked here so that every bad value
// is an InputError naming the option (the tool exits with 2 on it).
//
//   split_list("--material", "Si,Au")          -> {"Si", "Au"}: comma-separated items, none empty
//   parse_number_list("--alpha", "45,60,90")   -> {45, 60, 90}: comma-separated finite numbers
//   parse_models("--model", "rigorous,sp")      -> the chain models (rigorous, unpolarized, sp,
//                                                  paper_literal), model_name() gives the name back
//   check_alphas / check_thetas / check_wavelengths: the ranges the model and the data accept

#include <string>
#include <string_view>
#include <vector>

#include "materials/lobes/reflection_chain.h"

namespace ochre {

std::vector<std::string_view> split_list(std::string_view option, std::string_view text);
std::vector<double> parse_number_list(std::string_view option, std::string_view text);
std::vector<ChainModel> parse_models(std::string_view option, std::string_view text);
std::string_view model_name(ChainModel model);

// Dihedral angles in (0, 180] degrees.
void check_alphas(std::string_view option, const std::vector<double>& alphas_deg);
// Polar angles in [0, 90) degrees.
void check_thetas(std::string_view option, const std::vector<double>& thetas_deg);
// Wavelengths in the spectral range of the renderer's data, [360, 830] nm.
void check_wavelengths(std::string_view option, const std::vector<double>& wavelengths_nm);
// A reflection limit: 0 = none, else the largest number of reflections kept (Table 3 of the paper).
void check_reflection_limit(std::string_view option, int limit);

}  // namespace ochre
