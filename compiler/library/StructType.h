#pragma once
/// \file
/// Struct types: typedefs with <member>s (MaterialX 1.39 "Custom Data Types"), flattened to
/// their leaves, and the reading of struct literals such as "{0.1;0.5}" or "{{0.1;0.2};1}".
///
/// A struct value is carried as its leaves in depth-first member order: a member that is a
/// struct itself contributes its own leaves in place. Member access picks a contiguous range.

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "compiler/document/Value.h"

namespace mxc::lib {

class NodeLibrary;

struct StructType {
  struct Member {
    std::string_view name;
    std::string_view type;  ///< a value type, or another struct type
    size_t firstLeaf = 0;   ///< where its leaves start in the struct's leaves
    size_t leafCount = 0;   ///< 1 for a value member
  };
  struct Leaf {
    std::string path;                        ///< "ss", or "inner.x" for a member of a member
    doc::ValueType type = doc::ValueType::None;
    std::optional<doc::Value> defaultValue;  ///< the member's `value`, when it has one
  };
  std::string_view name;
  std::vector<Member> members;
  std::vector<Leaf> leaves;

  const Member* findMember(std::string_view memberName) const;
};

/// The leaves of struct literal `text` of type `type`: "{m0;m1;...}" with one part per member
/// (a struct member's part is itself braced). On failure the error's offset is into `text`.
std::variant<std::vector<doc::Value>, doc::ValueError> parseStructValue(const StructType& type,
                                                                        const NodeLibrary& library,
                                                                        std::string_view text);

}  // namespace mxc::lib
