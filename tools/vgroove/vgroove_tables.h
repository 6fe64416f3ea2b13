#pragma once
// Tables 1-3 of Saint-Pierre et al. 2019 recomputed with the exact model (materials/lobes/vgroove/),
// each value beside the printed one (vgroove_printed_tables.h).
//   Table 1: bi-hemispherical reflectance (%) at 550 nm, rigorous model: black glass (n = 1.5), the
//            renderer's Si, Au, Cu, Al at 550 nm and the paper's silver 0.1249 + 3.3391i.
//   Table 2: CIE 1994 Delta E (graphic arts) between the colours (vgroove_colour.h) of the spectral
//            bi-hemispherical reflectances of the rigorous model (the reference) and the unpolarized
//            model (rows glass, gold, copper, silicon) or the s/p model ("Silicon (sp)").
//   Table 3: the paper's silver, rays with more than 1-4 reflections discarded, rigorous model.
// Dihedral angles are computed in parallel; the results do not depend on the number of threads.

#include <string>
#include <vector>

namespace ochre {

struct TableValue {
  int table;        // 1, 2 or 3
  std::string row;  // the paper's row name (Table 3: "1 reflection", "2 reflections", ...)
  double alpha_deg;
  double ours, printed;
};

// quadrature_points: the n of the n x n Gauss-Legendre rule of bihemispherical_reflectance().
std::vector<TableValue> paper_table1(int quadrature_points);
std::vector<TableValue> paper_table2(int quadrature_points);
std::vector<TableValue> paper_table3(int quadrature_points);

}  // namespace ochre
