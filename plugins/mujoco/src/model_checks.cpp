// What the adapter checks of a user's model (model_checks.hpp).
#include "model_checks.hpp"

#include <string>

namespace wtc::mujoco {
namespace {

std::string geomName(const mjModel& m, int geom) {
  const char* name = mj_id2name(&m, mjOBJ_GEOM, geom);
  // Appended, not "'" + std::string(name): GCC 12 warns falsely of an
  // overlapping memcpy in that operator+ (its -Wrestrict, GCC bug 105329).
  std::string quoted = name != nullptr ? "'" : "#";
  quoted += name != nullptr ? std::string(name) + "'" : std::to_string(geom);
  return quoted;
}

bool onGround(const mjModel& m, int geom) { return m.body_weldid[m.geom_bodyid[geom]] == 0; }

// MuJoCo's <exclude body1 body2>: its signature ((body1 + 1) << 16) +
// body2 + 1 (mjmodel.h), either way round.
bool excluded(const mjModel& m, int a, int b) {
  for (int k = 0; k < m.nexclude; ++k) {
    const int s = m.exclude_signature[k];
    if (s == ((a + 1) << 16) + b + 1 || s == ((b + 1) << 16) + a + 1) return true;
  }
  return false;
}

}  // namespace

std::string worldCollision(const mjModel& m, int body) {
  if ((m.opt.disableflags & mjDSBL_CONTACT) != 0) return {};
  for (int k = 0; k < m.npair; ++k) {
    const int g1 = m.pair_geom1[k], g2 = m.pair_geom2[k];
    const bool one = m.geom_bodyid[g1] == body && onGround(m, g2), two = m.geom_bodyid[g2] == body && onGround(m, g1);
    if (one || two) {
      return "<pair> " + std::to_string(k) + " collides geom " + geomName(m, one ? g1 : g2) +
             " with the ground's geom " + geomName(m, one ? g2 : g1);
    }
  }
  for (int g = 0; g < m.ngeom; ++g) {
    if (m.geom_bodyid[g] != body) continue;
    for (int w = 0; w < m.ngeom; ++w) {
      if (!onGround(m, w) || excluded(m, body, m.geom_bodyid[w])) continue;
      if ((m.geom_contype[g] & m.geom_conaffinity[w]) != 0 || (m.geom_contype[w] & m.geom_conaffinity[g]) != 0) {
        return "geom " + geomName(m, g) + " (contype " + std::to_string(m.geom_contype[g]) + ", conaffinity " +
               std::to_string(m.geom_conaffinity[g]) + ") collides with the ground's geom " + geomName(m, w) +
               " (contype " + std::to_string(m.geom_contype[w]) + ", conaffinity " +
               std::to_string(m.geom_conaffinity[w]) + ")";
      }
    }
  }
  return {};
}

}  // namespace wtc::mujoco
