#pragma once
// Who may do what on a project: four roles, each allowed everything the ones below it are.
// viewer reads; reviewer also writes review items and comments; designer also uploads versions
// and starts checks; owner also manages the members. A user's role on the server (given by
// `mtcs serve --add-user`) decides who may create projects; an owner of the server owns every
// project.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mtcs::serve {

enum class Role { viewer = 0, reviewer = 1, designer = 2, owner = 3 };

std::string to_string(Role role);
std::optional<Role> role_from(std::string_view name);
inline bool at_least(Role have, Role need) { return int(have) >= int(need); }

// What a role may do to a project's review items, sent with each item so that a page shows only
// what the server would accept (BCF-API's authorization.topic_actions).
std::vector<std::string> topic_actions(Role role);
// The statuses an item can take, in the order of its workflow.
const std::vector<std::string>& topic_statuses();

}  // namespace mtcs::serve
