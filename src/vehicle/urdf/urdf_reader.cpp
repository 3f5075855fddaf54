// A URDF file to a VehicleDescription (wtc/vehicle/urdf_file.hpp). The
// steps, in order, each refusing what it cannot map before the next one
// relies on it: parse (urdfdom) -> the tree (one parent per link, every
// link reached from the root: no walk before that is known) -> joint types
// -> link frames in V -> masses and inertias per link -> fixed links merged
// into groups -> one body per group in file order -> joints -> collision
// shapes -> mimics.
#include <cmath>
#include <deque>
#include <iomanip>
#include <set>
#include <sstream>

#include <urdf_model/model.h>

#include "collision_shapes.hpp"
#include "urdf_parse.hpp"
#include "wtc/base/error.hpp"
#include "wtc/vehicle/principal_inertia.hpp"
#include "wtc/vehicle/urdf_file.hpp"

namespace wtc::vehicle {
namespace {

using detail::toIsometry;

struct Refuser {
  std::string file;
  [[noreturn]] void link(const std::string& name, const std::string& problem) const {
    throw InvalidInputError(file + ": link '" + name + "' " + problem);
  }
  [[noreturn]] void joint(const std::string& name, const std::string& problem) const {
    throw InvalidInputError(file + ": joint '" + name + "' " + problem);
  }
};

// The parent joint of every link but the root; refuses a link that is the
// child of two joints and a link the root does not reach (a cycle).
std::map<std::string, urdf::JointSharedPtr> parentJoints(const urdf::ModelInterface& model, const Refuser& refuse) {
  std::map<std::string, urdf::JointSharedPtr> parent;
  for (const auto& [name, joint] : model.joints_) {  // name order
    const auto [it, added] = parent.emplace(joint->child_link_name, joint);
    if (!added) {
      refuse.link(joint->child_link_name, "is the child of two joints ('" + it->second->name + "' and '" + name +
                                              "'): a closed chain, which a tree of bodies cannot hold");
    }
  }
  // Every link reached from the root, breadth first, each once.
  std::set<std::string> reached{model.getRoot()->name};
  std::deque<std::string> queue{model.getRoot()->name};
  while (!queue.empty()) {
    const std::string at = queue.front();
    queue.pop_front();
    for (const auto& [name, joint] : model.joints_) {
      if (joint->parent_link_name == at && reached.insert(joint->child_link_name).second) {
        queue.push_back(joint->child_link_name);
      }
    }
  }
  for (const auto& [name, link] : model.links_) {
    if (!reached.count(name)) {
      refuse.link(name, "is not reached from the root link '" + model.getRoot()->name +
                            "': its joints close a chain (a cycle), which a tree of bodies cannot hold");
    }
  }
  return parent;
}

const char* typeName(int type) {
  switch (type) {
    case urdf::Joint::REVOLUTE:
      return "revolute";
    case urdf::Joint::CONTINUOUS:
      return "continuous";
    case urdf::Joint::PRISMATIC:
      return "prismatic";
    case urdf::Joint::FLOATING:
      return "floating";
    case urdf::Joint::PLANAR:
      return "planar";
    case urdf::Joint::FIXED:
      return "fixed";
    default:
      return "unknown";
  }
}

// A computed value (a principal moment) to 6 digits: -0.01, not its
// roundoff -0.009999999999999998.
std::string sixDigits(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

// One link's mass and tensor, checked: mass > 0, diagonal > 0, principal
// moments > 0 and obeying the triangle inequality.
void checkInertial(const urdf::Link& link, const Refuser& refuse) {
  const urdf::Inertial& in = *link.inertial;
  if (!std::isfinite(in.mass) || in.mass <= 0.0) {
    refuse.link(link.name, "has mass " + formatNumber(in.mass) + " kg: a body's mass must be finite and > 0");
  }
  const std::pair<const char*, double> diagonal[] = {{"ixx", in.ixx}, {"iyy", in.iyy}, {"izz", in.izz}};
  for (const auto& [key, value] : diagonal) {
    if (!std::isfinite(value) || value <= 0.0) {
      refuse.link(link.name, "has inertia " + std::string(key) + " = " + formatNumber(value) +
                                 " kg m^2, which is not positive (a body's moments must be finite and > 0)");
    }
  }
  Eigen::Matrix3d tensor;
  tensor << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  if (!tensor.allFinite()) refuse.link(link.name, "has an inertia tensor that is not finite");
  const Eigen::Vector3d m = principalInertia(tensor).moments;
  for (int k = 0; k < 3; ++k) {
    if (m[k] <= 0.0) {
      refuse.link(link.name, "has an inertia tensor with principal moment " + sixDigits(m[k]) +
                                 " kg m^2, which is not positive (the tensor is not positive definite)");
    }
  }
  const double slack = 1e-9 * m.sum();
  if (m.x() + m.y() < m.z() - slack || m.y() + m.z() < m.x() - slack || m.z() + m.x() < m.y() - slack) {
    refuse.link(link.name, "has principal moments " + formatVector(m) +
                               " kg m^2 that violate the triangle inequality (no rigid body has them)");
  }
}

// A group: a link that is a body and the links merged into it.
struct Group {
  std::string link;                  ///< The body's own link.
  std::vector<std::string> members;  ///< It and every link merged into it, parents first.
};

}  // namespace

UrdfModel readUrdf(const std::filesystem::path& file, const UrdfOptions& options) {
  const Refuser refuse{file.string()};
  detail::ParsedUrdf parsed = detail::parseUrdfFile(file);
  const urdf::ModelInterface& model = *parsed.model;
  const auto parent_joint = parentJoints(model, refuse);

  for (const auto& [name, joint] : model.joints_) {
    if (joint->type == urdf::Joint::FLOATING || joint->type == urdf::Joint::PLANAR) {
      refuse.joint(name, std::string("is ") + typeName(joint->type) +
                             ": WTC's bodies hang by revolute, continuous, prismatic or fixed joints");
    }
  }

  // Link frames in V (the root's frame), parents first (breadth first).
  std::map<std::string, Eigen::Isometry3d> X_VL{{model.getRoot()->name, Eigen::Isometry3d::Identity()}};
  std::vector<std::string> tree_order{model.getRoot()->name};
  for (std::size_t i = 0; i < tree_order.size(); ++i) {
    for (const auto& [name, joint] : model.joints_) {
      if (joint->parent_link_name != tree_order[i]) continue;
      X_VL[joint->child_link_name] = X_VL[tree_order[i]] * toIsometry(joint->parent_to_joint_origin_transform);
      tree_order.push_back(joint->child_link_name);
    }
  }

  // Masses: a link without <inertial> is merged or refused.
  for (const auto& [name, link] : model.links_) {
    if (link->inertial) {
      checkInertial(*link, refuse);
    } else if (const auto it = parent_joint.find(name);
               it != parent_joint.end() && it->second->type != urdf::Joint::FIXED) {
      refuse.link(name, "has no mass (no <inertial>) and is on " + std::string(typeName(it->second->type)) +
                            " joint '" + it->second->name +
                            "': only a link on a fixed joint can be merged into its parent");
    }
  }

  // Groups: a link on a fixed joint joins its parent's.
  std::map<std::string, std::string> group_of;
  std::map<std::string, Group> groups;
  for (const std::string& name : tree_order) {
    const auto it = parent_joint.find(name);
    const bool merged = it != parent_joint.end() && it->second->type == urdf::Joint::FIXED;
    group_of[name] = merged ? group_of.at(it->second->parent_link_name) : name;
    Group& g = groups[group_of[name]];
    g.link = group_of[name];
    g.members.push_back(name);
  }

  // Bodies in the file's order of <link>s, a parent's before its children's.
  std::vector<std::string> order;
  std::vector<std::string> pending;
  for (const std::string& name : parsed.link_order) {
    if (group_of.at(name) == name) pending.push_back(name);
  }
  UrdfModel out;
  out.file = file;
  VehicleDescription& v = out.vehicle;
  v.name = model.getName();
  while (!pending.empty()) {
    for (auto it = pending.begin(); it != pending.end(); ++it) {
      const auto pj = parent_joint.find(*it);
      if (pj == parent_joint.end() || out.link_body.count(group_of.at(pj->second->parent_link_name))) {
        out.link_body[*it] = static_cast<int>(order.size());
        order.push_back(*it);
        pending.erase(it);
        break;
      }
    }
  }
  for (const auto& [name, group] : group_of) out.link_body[name] = out.link_body.at(group);

  for (const std::string& name : order) {
    const Group& g = groups.at(name);
    Body b;
    b.name = name;
    // Mass, centre and tensor in V, summed over the group (parallel axes:
    // I_C = sum R_i I_i R_i^T + m_i (|d_i|^2 E - d_i d_i^T), d_i = c_i - c).
    std::vector<std::pair<Eigen::Isometry3d, const urdf::Inertial*>> parts;
    for (const std::string& member : g.members) {
      const urdf::Inertial* in = model.links_.at(member)->inertial.get();
      if (in) parts.emplace_back(X_VL.at(member) * toIsometry(in->origin), in);
    }
    if (parts.empty()) {
      refuse.link(name, "has no mass (no <inertial>) and no link with mass is merged into it");
    }
    const auto tensorOf = [](const urdf::Inertial& in) {
      Eigen::Matrix3d t;
      t << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
      return t;
    };
    const auto diagonal = [](const urdf::Inertial& in) { return in.ixy == 0.0 && in.ixz == 0.0 && in.iyz == 0.0; };
    if (parts.size() == 1 && diagonal(*parts[0].second)) {
      // As given: no arithmetic on a diagonal tensor's moments or its centre.
      b.mass = parts[0].second->mass;
      b.pose = parts[0].first;
      b.inertia = tensorOf(*parts[0].second).diagonal();
    } else {
      Eigen::Vector3d moment = Eigen::Vector3d::Zero();
      for (const auto& [pose, in] : parts) {
        b.mass += in->mass;
        moment += in->mass * pose.translation();
      }
      const Eigen::Vector3d c = moment / b.mass;
      Eigen::Matrix3d I_V = Eigen::Matrix3d::Zero();
      for (const auto& [pose, in] : parts) {
        const Eigen::Vector3d d = pose.translation() - c;
        I_V += pose.linear() * tensorOf(*in) * pose.linear().transpose() +
               in->mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      }
      // The tensor in the body link's axes, then its principal axes.
      const Eigen::Matrix3d R_VL = X_VL.at(name).linear();
      const PrincipalInertia p = principalInertia(R_VL.transpose() * I_V * R_VL);
      b.inertia = p.moments;
      b.pose.linear() = R_VL * p.rotation;
      b.pose.translation() = c;
    }

    // The link's axes in the body's frame (R_BL = R_VB^T R_VL): users read
    // the link's rotation, not the principal axes' (nor an <inertial>'s rpy).
    b.own_axes = b.pose.linear().transpose() * X_VL.at(name).linear();

    if (const auto pj = parent_joint.find(name); pj != parent_joint.end()) {
      const urdf::Joint& j = *pj->second;
      b.parent = out.link_body.at(j.parent_link_name);
      b.joint.name = j.name;
      b.joint.anchor = X_VL.at(name).translation();
      b.joint.axis = X_VL.at(name).linear() * Eigen::Vector3d(j.axis.x, j.axis.y, j.axis.z);
      b.joint.type = j.type == urdf::Joint::PRISMATIC ? JointType::kPrismatic : JointType::kRevolute;
      // A continuous joint has no travel: urdfdom hands back lower = upper = 0 with its effort and velocity.
      if (j.type != urdf::Joint::CONTINUOUS && j.limits) b.joint.limits = JointLimits{j.limits->lower, j.limits->upper};
      out.joint_body[j.name] = static_cast<int>(v.bodies.size());
      out.drive_limits[j.name] = j.limits ? UrdfDriveLimits{j.limits->effort, j.limits->velocity} : UrdfDriveLimits{};
    }

    detail::CollisionContext context{file, options.package_path};
    std::vector<ShapePart> shapes;
    for (const std::string& member : g.members) {
      detail::addCollisionShapes(*model.links_.at(member), b.pose.inverse() * X_VL.at(member), context, shapes);
    }
    detail::setBodyShape(b, std::move(shapes));
    v.bodies.push_back(std::move(b));
  }

  for (const auto& [name, joint] : model.joints_) {
    if (!joint->mimic) continue;
    const auto master = model.joints_.find(joint->mimic->joint_name);
    if (master == model.joints_.end()) {
      refuse.joint(name, "mimics '" + joint->mimic->joint_name + "', which is not a joint of " + file.string());
    }
    if (joint->type == urdf::Joint::FIXED || master->second->type == urdf::Joint::FIXED) {
      refuse.joint(name, "mimics '" + master->first + "': a fixed joint neither mimics nor is mimicked");
    }
    v.bodies[out.joint_body.at(name)].joint.mimic = Mimic{.master = out.joint_body.at(master->first),
                                                          .multiplier = joint->mimic->multiplier,
                                                          .offset = joint->mimic->offset};
  }

  validate(v, file.string());
  return out;
}

}  // namespace wtc::vehicle
