#pragma once
// GraphError: a material graph the compiler rejects. The message names where the fault is:
//   "<file>: material '<m>', node '<n>', parameter '<p>': <what>"
// with the empty parts left out (a one-node shorthand material has no node name).

#include <stdexcept>
#include <string>

namespace ochre {

class GraphError : public std::runtime_error {
 public:
  GraphError(std::string file, std::string material, std::string node, std::string parameter,
             const std::string& what);

  const std::string& file() const { return file_; }
  const std::string& material() const { return material_; }
  const std::string& node() const { return node_; }
  const std::string& parameter() const { return parameter_; }
  // The description without the location prefix.
  const std::string& reason() const { return reason_; }

 private:
  std::string file_, material_, node_, parameter_, reason_;
};

}  // namespace ochre
