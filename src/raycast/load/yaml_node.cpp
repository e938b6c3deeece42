#include "load/yaml_node.h"

namespace raycast {

std::size_t YamlNode::size() const { return IsSequence() || IsMap() ? data_->size : 0; }

YamlNode YamlNode::operator[](std::size_t i) const {
  if (!IsSequence() || i >= data_->size) return YamlNode();
  return YamlNode(entries()[i]);
}

YamlNode YamlNode::operator[](std::string_view key) const {
  // Mappings are small (a handful of fields): a scan beats any index, and the first of a key
  // given twice answers, as yaml-cpp does (Fields rejects repeated keys with both positions).
  for (const YamlPair& kv : pairs_of(*this)) {
    const YamlNodeData* k = kv.key_data;
    if (k->type == YamlType::kScalar &&
        std::string_view(static_cast<const char*>(k->items), k->size) == key)
      return YamlNode(kv.value_data);
  }
  return YamlNode();
}

YamlNode::SequenceIterator YamlNode::begin() const {
  return SequenceIterator(IsSequence() ? entries() : nullptr);
}

YamlNode::SequenceIterator YamlNode::end() const {
  return SequenceIterator(IsSequence() ? entries() + data_->size : nullptr);
}

const YamlPair* YamlNode::pairs_begin() const {
  return IsMap() ? static_cast<const YamlPair*>(data_->items) : nullptr;
}
const YamlPair* YamlNode::pairs_end() const {
  return IsMap() ? pairs_begin() + data_->size : nullptr;
}

const YamlNodeData* const* YamlNode::entries() const {
  return static_cast<const YamlNodeData* const*>(data_->items);
}

YamlDocument::YamlDocument() = default;
YamlDocument::YamlDocument(YamlDocument&&) noexcept = default;
YamlDocument& YamlDocument::operator=(YamlDocument&&) noexcept = default;
YamlDocument::~YamlDocument() = default;

}  // namespace raycast
