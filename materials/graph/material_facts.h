#pragma once
// MaterialFacts: what the compiler learned about a material, so the renderer models only what the
// scene needs (polarization mode, NEE for delta lobes, UV / vertex-colour attributes, spectral work).

namespace ochre {

struct MaterialFacts {
  bool has_lobes = false;            // some BSDF lobe can be produced
  bool is_emissive = false;          // emission reachable with non-zero constant or non-constant strength
  bool polarizes = false;            // some reachable lobe declares kLobePolarizing
  bool has_delta_lobes = false;      // some reachable lobe declares kLobeDelta
  bool needs_uv = false;             // a texture or uv node is reachable
  bool needs_vertex_colour = false;  // a vertex_colour node is reachable
  // No reachable node reads the shading point (uv, vertex colour, textures, position, normal): the result
  // depends on the wavelengths alone, so e.g. an area light may reuse its emission for the same wavelengths.
  bool uniform_over_surface = false;
  bool spectrally_varying = false;  // some spectrum used is not constant over wavelength
  int nodes_declared = 0;           // nodes written in the scene
  int nodes_compiled = 0;           // declared nodes left as instructions after folding and dead-node removal
};

}  // namespace ochre
