// The node types ochre ships. Adding a node: write its file (one function returning its
// NodeDefinition) and add one line to each list below.
//
// (Self-registration through static objects would drop the list, but ochre_materials is a static
// library: the linker discards object files nothing references, and their registrations with them.)

#include "materials/nodes/node_registry.h"

namespace ochre {

// Values.
NodeDefinition constant_node();
NodeDefinition spectrum_node();
NodeDefinition rgb_to_spectrum_node();
NodeDefinition texture_node();
NodeDefinition vertex_colour_node();
NodeDefinition uv_node();
NodeDefinition position_node();
NodeDefinition noise_node();
NodeDefinition projection_node();
// Math (values and closures).
NodeDefinition add_node();
NodeDefinition multiply_node();
NodeDefinition mix_node();
// Closures.
NodeDefinition lambert_node();
NodeDefinition emission_node();
NodeDefinition conductor_node();
NodeDefinition dielectric_node();
NodeDefinition lambert_sphere_node();
NodeDefinition oren_nayar_node();
NodeDefinition chandrasekhar_node();
NodeDefinition vgroove_node();
NodeDefinition microgroove_node();
NodeDefinition powder_node();

const NodeRegistry& NodeRegistry::builtin() {
  static const NodeRegistry registry = [] {
    NodeRegistry r;
    for (auto make : {constant_node,       spectrum_node,   rgb_to_spectrum_node, texture_node,
                      vertex_colour_node,  uv_node,         position_node,        noise_node,
                      projection_node,     add_node,        multiply_node,        mix_node,
                      lambert_node,        emission_node,   conductor_node,       dielectric_node,
                      lambert_sphere_node, oren_nayar_node, chandrasekhar_node,   vgroove_node,
                      microgroove_node,    powder_node})
      r.add(make());
    return r;
  }();
  return registry;
}

}  // namespace ochre
