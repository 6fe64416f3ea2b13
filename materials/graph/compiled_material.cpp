#include "materials/graph/compiled_material.h"

#include <cstring>
#include <stdexcept>

#include "spectra/wavelength_memo.h"

namespace ochre {

namespace {

void append_registers(std::string& text, const uint16_t* registers, int count) {
  for (int k = 0; k < count; ++k) {
    if (k > 0) text += ',';
    text += std::to_string(registers[k]);
  }
}

}  // namespace

CompiledMaterial::CompiledMaterial(std::string name, MaterialFacts facts, Program program)
    : name_(std::move(name)),
      facts_(facts),
      program_(std::move(program)),
      memo_key_(new_wavelength_memo_key()) {}

void CompiledMaterial::evaluate(const ShadingContext& ctx, LobeArena& arena, Closure& out) const {
  if (!ctx.lambda) throw std::invalid_argument("material '" + name_ + "': ShadingContext::lambda is not set");
  float frame[kMaxFrameFloats];
  std::memcpy(frame, program_.initial_frame.data(), program_.initial_frame.size() * sizeof(float));
  out.clear();

  const uint16_t* operands = program_.operands.data();
  auto args = [&](const Instruction& ins) {
    const uint16_t* in = operands + ins.first_operand;
    return NodeArgs{ctx, frame, in, in + ins.input_count, ins.payload, ins.outputs_used, arena, out};
  };
  for (const Instruction& ins : program_.values)
    if (ins.gate == kUngated || frame[ins.gate] != 0.0f) ins.fn(args(ins));
  for (const Instruction& ins : program_.closures) {
    const NodeArgs a = args(ins);
    if (!a.weight().is_black()) ins.fn(a);  // a closure nobody gives weight to adds nothing
  }
}

int CompiledMaterial::instruction_count() const {
  return static_cast<int>(program_.values.size() + program_.closures.size());
}

std::string CompiledMaterial::listing() const {
  std::string text;
  auto list = [&](const std::vector<Instruction>& instructions, const std::vector<std::string>& labels) {
    for (size_t i = 0; i < instructions.size(); ++i) {
      const Instruction& ins = instructions[i];
      text += labels[i] + "  in[";
      append_registers(text, &program_.operands[ins.first_operand], ins.input_count);
      text += "] out[";
      append_registers(text, &program_.operands[ins.first_operand + ins.input_count], ins.output_count);
      text += "]";
      if (ins.gate != kUngated) text += " skipped while [" + std::to_string(ins.gate) + "] = 0";
      text += "\n";
    }
  };
  list(program_.values, program_.value_labels);
  list(program_.closures, program_.closure_labels);
  return text;
}

}  // namespace ochre
