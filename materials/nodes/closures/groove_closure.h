#pragma once
// What the groove closures (vgroove, microgroove) share: the facet material and polarization model
// parameters, the groove direction on the surface, and their socket and parameter definitions.

#include <string>

#include "materials/lobes/vgroove/groove_frame.h"
#include "materials/nodes/node_definition.h"
#include "spectra/spectrum.h"

namespace ochre {

enum class DirectionSpace { kUV, kObject, kWorld };

struct GrooveFacetSettings {
  SpectrumPtr eta, k;  // named optical constants, or null (the eta and k inputs)
  bool mirror = false;
  ChainModel model = ChainModel::kRigorous;
  int reflection_limit = 0;
  DirectionSpace space = DirectionSpace::kUV;
};

// The parameters `metal`, `model`, `max_reflections` and `direction_space`.
GrooveFacetSettings parse_groove_settings(const PrepareArgs& args);

// Input indices of the shared sockets in a groove closure's definition.
struct GrooveInputs {
  int eta, k, angle, direction;
};

// The facet material at the path's wavelengths.
FacetSpectrum groove_facet(const NodeArgs& a, const GrooveFacetSettings& s, const GrooveInputs& in);

// The groove axis in the local frame the renderer will build (closure.h, set_tangent): the reference
// direction projected onto the tangent plane and turned by `angle` degrees about the normal. The first
// groove closure of a material sets the closure's tangent and gets local x; later ones get their axis
// relative to it.
Vec3 groove_local_axis(const NodeArgs& a, const GrooveFacetSettings& s, const GrooveInputs& in);

ClosureTraits groove_traits(const GrooveFacetSettings& s);

// Socket and parameter definitions shared by the groove closures (documented in docs/nodes.md).
std::vector<SocketDef> groove_facet_and_direction_inputs();  // eta, k, angle, direction
std::vector<ParamDef> groove_common_params();                // metal, model, max_reflections, direction_space

}  // namespace ochre
