#pragma once
// The CPU backend's kernel (cpu/interpreter.inl) in both precisions:
// sdfwb::cpu::f32 and sdfwb::cpu::f64. Everything in it is inline, so the
// renderer, the picker and the conformance tests share one instantiation.

#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "expr/tape.h"
#include "image/mipmapped_images.h"
#include "program/program.h"
#include "program/scene_images.h"
#include "prune/prune_grid.h"
#include "sdf/shared.h"

namespace sdfwb::cpu {

namespace f32 {
using namespace sdfwb::sdf::f32;
#include "cpu/interpreter.inl"
}  // namespace f32

namespace f64 {
using namespace sdfwb::sdf::f64;
#include "cpu/interpreter.inl"
}  // namespace f64

}  // namespace sdfwb::cpu
