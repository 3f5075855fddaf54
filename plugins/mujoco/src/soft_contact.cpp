// One WTC contact as an mjContact: the mapping of soft_contact.hpp.
#include "soft_contact.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace wtc::mujoco {

bool toSoftContact(const SolverContact& c, const ContactSetting& s, SoftContact& out) {
  const double h = s.step_seconds;
  const double spring = h * c.stiffness + c.damping;  // h c + b (N s/m)
  if (!(spring > 0.0)) return false;
  const double target = 1.0 / (h * spring);  // R* (1/kg)
  const double mu = c.friction;
  const int dim = mu >= mjMINMU ? 3 : 1;
  const double impratio = std::max(mjMINVAL, s.impratio);
  // The normal row's R before a pyramid's rescaling (R_0), and its D.
  const bool pyramid = s.pyramidal && dim > 1;
  const double edges = 2.0 * (dim - 1);
  const double to_row = pyramid ? edges * impratio / (2.0 * mu * mu) : 1.0;  // R_0 / R_normal
  const double diag = pyramid ? s.inverse_weight * (1.0 + mu * mu) : s.inverse_weight;
  const double d = std::clamp(diag / (diag + to_row * target), mjMINIMP, mjMAXIMP);
  const double row = (1.0 - d) / d * diag;  // R_0 as MuJoCo will compute it
  const double normal = row / to_row;       // the normal's R as solved

  mjContact& m = out.contact;
  m = mjContact{};
  m.dist = -c.depth;
  for (int i = 0; i < 3; ++i) m.pos[i] = c.tread_point[i];
  // frame: the normal (geom1, the ground, toward geom2, the wheel), then
  // the friction's first direction and the second, n x t1.
  const Eigen::Vector3d n = c.normal.normalized();
  Eigen::Vector3d t1 = c.friction_direction - c.friction_direction.dot(n) * n;
  t1 = t1.norm() > 0.0 ? t1.normalized() : n.unitOrthogonal();
  const Eigen::Vector3d t2 = n.cross(t1);
  for (int i = 0; i < 3; ++i) {
    m.frame[i] = n[i];
    m.frame[3 + i] = t1[i];
    m.frame[6 + i] = t2[i];
  }
  m.includemargin = 0.0;
  // One friction direction, along the traction (t1), as in ODE's constraint
  // mode (plugins/ode/src/contact_joint.cpp says why): grip across comes
  // from the tread state turning toward a new slip, from step to step.
  // MuJoCo's least coefficient stands for none across.
  m.friction[0] = dim > 1 ? mu : 0.0;
  m.friction[1] = dim > 1 ? mjMINMU : 0.0;
  m.solref[0] = -d * c.stiffness * normal;  // k = d c R: K I = k / d = c R
  m.solref[1] = -d / h;                     // b' = d / h: B = b' / d = 1 / h
  m.solimp[0] = m.solimp[1] = d;            // constant: I = 0.5 (d + d) = d
  m.solimp[2] = 0.0;                        // (width, midpoint and power unused then)
  m.solimp[3] = 0.5;
  m.solimp[4] = 1.0;
  m.dim = dim;
  m.geom1 = s.ground_geom;
  m.geom2 = s.wheel_geom;
  m.exclude = 0;
  m.efc_address = -1;

  out.regularizer = normal;
  out.damping = 1.0 / (h * normal) - h * c.stiffness;
  out.slip_per_newton = dim > 1 ? h * row / impratio : 0.0;
  return true;
}

}  // namespace wtc::mujoco
