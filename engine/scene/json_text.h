#pragma once
// Strict reading of JSON text, before any scene field is looked at.
//
// nlohmann::json accepts things a scene file must not contain: it stops at a
// NUL byte and ignores the rest, lets the last of two equal keys win, and
// nests as deep as memory allows (the scene reader and every tree walk after
// it recurse). A check pass over the text (SAX, no tree built) refuses all of
// these with a location before the document is built.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace sdfwb::scene {

// Nesting of arrays and objects: deep enough for a node tree of kMaxNodeDepth
// levels (a node is an object in its parent's "children" array: two levels
// per node, one for the scene object, one for a node's vec3 fields) and one
// level more, so that a too deep tree gets the node-depth message with its path.
inline constexpr std::size_t kMaxJsonDepth = 2 * (static_cast<std::size_t>(kMaxNodeDepth) + 1) + 2;

// One problem of the text: "line L, column C: <reason>" or "<json path>: <reason>".
class JsonTextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Parses `text` as one JSON document. Throws JsonTextError for invalid JSON,
// a NUL byte, bytes after the document, a non-finite number (1e999), a key
// given twice in one object, or nesting deeper than kMaxJsonDepth.
nlohmann::ordered_json parseStrictJson(std::string_view text);

// A JSON path shortened for a one-line message: a path of a deep tree keeps
// its start and its end ("root.children[0].chi ... .children[3].radius").
std::string abbreviatedPath(std::string_view path);

}  // namespace sdfwb::scene
