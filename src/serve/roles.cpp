#include "mtcs/serve/roles.h"

namespace mtcs::serve {

std::string to_string(Role role) {
  switch (role) {
    case Role::viewer: return "viewer";
    case Role::reviewer: return "reviewer";
    case Role::designer: return "designer";
    case Role::owner: return "owner";
  }
  return "viewer";
}

std::optional<Role> role_from(std::string_view name) {
  for (Role r : {Role::viewer, Role::reviewer, Role::designer, Role::owner})
    if (name == to_string(r)) return r;
  return std::nullopt;
}

std::vector<std::string> topic_actions(Role role) {
  if (!at_least(role, Role::reviewer)) return {};
  return {"update", "updateStatus", "createComment", "createViewpoint"};
}

const std::vector<std::string>& topic_statuses() {
  static const std::vector<std::string> statuses{"open", "in_progress", "resolved", "closed"};
  return statuses;
}

}  // namespace mtcs::serve
