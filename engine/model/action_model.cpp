#include "model/action_model.h"

namespace pat {
namespace {

template <typename T>
int find_named(const std::vector<T>& items, const std::string& name) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

int ActionModel::body_index(const std::string& n) const {
  return find_named(bodies, n);
}
int ActionModel::contact_index(const std::string& n) const {
  return find_named(contacts, n);
}
int ActionModel::spring_index(const std::string& n) const {
  return find_named(springs, n);
}
int ActionModel::strap_index(const std::string& n) const {
  return find_named(straps, n);
}
int ActionModel::adjuster_index(const std::string& n) const {
  return find_named(adjusters, n);
}
int ActionModel::setting_index(const std::string& n) const {
  return find_named(regulation, n);
}

}  // namespace pat
