// A compact heightfield or triangle mesh in Bullet (issue 18): one
// heightfield or triangle-mesh shape, not a hull per prism, with the
// prisms' surface; Bullet's other bodies collide with it, a contact names
// the prism it met, and WTC's wheels run exactly as on the stored prisms.
// Each case runs on the scene's field and on the same surface as a mesh
// (surfaceMesh). docs/terrain.md.
#include <BulletCollision/CollisionDispatch/btConvexConcaveCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_fixture.hpp"
#include "random_heightfield.hpp"
#include "wtc/bullet/terrain_object.hpp"
#include "wtc/terrain/heightfield.hpp"

namespace wtc {
namespace {

using testing::BulletWorld;
using testing::PluginFieldScene;
using testing::pluginFieldScene;

// Every leaf shape of a (possibly nested) compound.
void leaves(const btCollisionShape& shape, std::vector<const btCollisionShape*>& out) {
  if (!shape.isCompound()) {
    out.push_back(&shape);
    return;
  }
  const auto& compound = static_cast<const btCompoundShape&>(shape);
  for (int k = 0; k < compound.getNumChildShapes(); ++k) leaves(*compound.getChildShape(k), out);
}

// The parameter: the compact part is the field, its mesh, or the field with
// holes (which the plugin gives the engine as its mesh).
class BulletCompactTerrainTest : public ::testing::TestWithParam<testing::CompactPart> {
 protected:
  PluginFieldScene scene(bool compact, double amplitude = 0.15) const {
    return pluginFieldScene(compact, amplitude, GetParam());
  }
  // Whether the engine gets a triangle mesh (the mesh, and the field with
  // holes), not its heightfield.
  bool engineMesh() const { return GetParam() != testing::CompactPart::kField; }
};

// Case: the compact part is one child, Bullet's heightfield or triangle
// mesh shape; the stored ledge keeps its hulls, each named by its piece id.
TEST_P(BulletCompactTerrainTest, ACompactPartIsOneShapeBesideTheStoredHulls) {
  const PluginFieldScene scene = this->scene(true);
  const bullet::TerrainObject object(scene.terrain);
  std::vector<const btCollisionShape*> shapes;
  leaves(*object.object().getCollisionShape(), shapes);
  int fields = 0;
  std::vector<PieceId> hull_ids;
  for (const btCollisionShape* shape : shapes) {
    if (shape->getShapeType() == (engineMesh() ? TRIANGLE_MESH_SHAPE_PROXYTYPE : TERRAIN_SHAPE_PROXYTYPE)) ++fields;
    if (shape->getShapeType() == CONVEX_HULL_SHAPE_PROXYTYPE) hull_ids.push_back(shape->getUserIndex());
  }
  EXPECT_EQ(fields, 1);
  ASSERT_EQ(hull_ids.size(), scene.terrain.pieces().size());
  for (std::size_t s = 0; s < hull_ids.size(); ++s) {
    EXPECT_EQ(hull_ids[s], static_cast<PieceId>(s));  // the ledge was added first
    EXPECT_FALSE(scene.terrain.isFormed(hull_ids[s]));
  }
  EXPECT_EQ(shapes.size(), hull_ids.size() + 1);
}

// Case: a ray down onto the field meets the prisms' top surface
// (surfaceHeight): the same cells, split along the same diagonal, at the
// same place.
TEST_P(BulletCompactTerrainTest, ARayMeetsTheSurfaceOfThePrisms) {
  constexpr double kRayToleranceM = 1e-9;  // double-precision ray-triangle intersection (m)
  const PluginFieldScene scene = this->scene(true);
  BulletWorld w(scene.terrain, ContactMode::kForce);
  std::mt19937 gen(7);
  int holes = 0;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector2d p = testing::randomPointOn(scene.field, gen, 1e-6);
    const btVector3 from(p.x(), p.y(), 20.0), to(p.x(), p.y(), 0.0);
    btCollisionWorld::ClosestRayResultCallback hit(from, to);
    w.world.rayTest(from, to, hit);
    const std::optional<double> surface = surfaceHeight(scene.field, p.x(), p.y());
    holes += !surface;
    ASSERT_EQ(hit.hasHit(), surface.has_value()) << "at (" << p.x() << ", " << p.y() << ")";  // through a hole
    if (surface) {
      EXPECT_NEAR(hit.m_hitPointWorld.z(), *surface, kRayToleranceM) << "at (" << p.x() << ", " << p.y() << ")";
    }
  }
  EXPECT_EQ(holes > 0, scene.field.hasHoles());
}

constexpr double kOnPrismM = 1e-9;  // a contact's ground point lies on its prism's top (m)

// Checks each contact Bullet reports between a probe and the terrain:
// TerrainObject::pieceOf names a formed prism that holds the contact's
// ground point. Counts the contacts, and those on pieces from `far_from` on.
struct NamesItsPrism : btCollisionWorld::ContactResultCallback {
  const bullet::TerrainObject* object = nullptr;
  const Terrain* terrain = nullptr;
  PieceId far_from = std::numeric_limits<PieceId>::max();
  int contacts = 0, far = 0;
  btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                           const btCollisionObjectWrapper* b, int, int) override {
    const bool a_is_ground = a->getCollisionObject() == &object->object();
    const PieceId id = object->pieceOf(a_is_ground ? *a : *b);
    const btVector3 at = a_is_ground ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
    EXPECT_TRUE(id >= 0 && terrain->isFormed(id)) << "piece " << id;
    if (id >= 0 && terrain->isFormed(id)) {
      std::optional<ConvexPolyhedron> scratch;
      EXPECT_LE(testing::outside(terrain->piece(id, scratch), Eigen::Vector3d(at.x(), at.y(), at.z())), kOnPrismM)
          << "piece " << id << " at (" << at.x() << ", " << at.y() << ", " << at.z() << ")";
    }
    ++contacts;
    far += id >= far_from;
    return 0;
  }
};

// The check for `terrain` in `w`, counting the contacts from piece `far_from` on.
NamesItsPrism namesItsPrism(BulletWorld& w, const Terrain& terrain, PieceId far_from) {
  NamesItsPrism check;
  check.object = &w.plugin->terrainShapes();
  check.terrain = &terrain;
  check.far_from = far_from;
  return check;
}

// A 5 cm sphere in the world, pressed into the ground where asked, each
// contact it makes with the terrain handed to `check`.
struct SphereProbe {
  explicit SphereProbe(BulletWorld& world) : w(world) {
    object.setCollisionShape(&ball);
    w.world.addCollisionObject(&object);
  }
  ~SphereProbe() { w.world.removeCollisionObject(&object); }
  void press(double x, double y, double z, NamesItsPrism& check) {
    object.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(x, y, z)));
    w.world.contactPairTest(&object, &w.plugin->terrainObject(), check);
  }
  BulletWorld& w;
  btSphereShape ball{0.05};
  btCollisionObject object;
};

// Case: a small sphere pressed into the field at random places; every
// contact Bullet reports names (TerrainObject::pieceOf) a prism that holds
// the contact's ground point.
TEST_P(BulletCompactTerrainTest, AContactNamesThePrismItMet) {
  const PluginFieldScene scene = this->scene(true);
  BulletWorld w(scene.terrain, ContactMode::kForce);
  SphereProbe probe(w);
  NamesItsPrism check;
  check.object = &w.plugin->terrainShapes();
  check.terrain = &scene.terrain;
  std::mt19937 gen(11);
  int presses = 0;
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector2d p = testing::randomPointOn(scene.field, gen, 0.1);
    const std::optional<double> surface = surfaceHeight(scene.field, p.x(), p.y());
    if (!surface) continue;                             // over a hole
    probe.press(p.x(), p.y(), *surface + 0.04, check);  // 1 cm into the ground
    ++presses;
  }
  EXPECT_GE(presses, 290);
  EXPECT_GE(check.contacts, presses);
}

// Case: a box (a chassis, 0.6 x 0.4 x 0.2 m) dropped on the field's flat
// patch comes to rest on it, as on the stored prisms.
TEST_P(BulletCompactTerrainTest, ABoxDroppedOnTheFieldRestsOnItsSurface) {
  constexpr double kRestM = 0.005;  // Bullet's margins: a few mm (as for the ledge)
  for (const bool compact : {true, false}) {
    const PluginFieldScene scene = this->scene(compact);
    BulletWorld w(scene.terrain, ContactMode::kForce);
    const double top = scene.field.origin.z() + PluginFieldScene::kPatchHeightM;
    btBoxShape box(btVector3(0.3, 0.2, 0.1));
    btDefaultMotionState motion(btTransform(btQuaternion::getIdentity(), btVector3(2.0, 8.0, top + 0.3)));
    btRigidBody chassis(btRigidBody::btRigidBodyConstructionInfo(10.0, &motion, &box, btVector3(0.2, 0.4, 0.5)));
    w.world.addRigidBody(&chassis);
    for (int k = 0; k < 2000; ++k) w.world.stepSimulation(1e-3, 1, 1e-3);
    EXPECT_NEAR(chassis.getCenterOfMassPosition().z(), top + 0.1, kRestM) << (compact ? "compact" : "prisms");
    EXPECT_LT(chassis.getLinearVelocity().norm(), 1e-2) << (compact ? "compact" : "prisms");
    w.world.removeRigidBody(&chassis);
  }
}

// Case: WTC answers the wheels from the terrain, not from Bullet's shapes:
// a wheel rolled 2 s over a rough field moves on the compact field (met as
// one surface, wtc/contact/wheel_contact.hpp) within a millimetre of its path
// on the stored prisms (met prism by prism; the same contacts, rounded
// differently). (Where a cut cap touches, Bullet
// collides the wheel's own cylinder with its shapes, heightfield or
// hulls; the field is gentle enough, +-4 cm, that none does.)
TEST_P(BulletCompactTerrainTest, AWheelRollsWithinAMillimetreOfTheStoredPrisms) {
  std::vector<btVector3> path[2];
  for (const bool compact : {true, false}) {
    const PluginFieldScene scene = this->scene(compact, 0.04);
    BulletWorld w(scene.terrain, ContactMode::kForce);
    const Eigen::Vector2d start(-2.0, 5.0);
    const double z = *surfaceHeight(scene.field, start.x(), start.y()) + 0.19 + 0.05;
    testing::BulletWheel& wheel = w.addWheelBody(3.7, btVector3(start.x(), start.y(), z));
    const bullet::WheelId id = testing::addWheel(w, wheel);
    wheel.body->setLinearVelocity(btVector3(1.5, 0.2, 0.0));
    wheel.body->setAngularVelocity(btVector3(0.0, 1.5 / 0.19, 0.0));
    for (int k = 0; k < 2000; ++k) {
      w.world.stepSimulation(1e-3, 1, 1e-3);
      path[compact ? 0 : 1].push_back(wheel.body->getCenterOfMassPosition());
      ASSERT_TRUE(w.plugin->state(id).capContacts().empty()) << "step " << k;
    }
  }
  ASSERT_EQ(path[0].size(), path[1].size());
  double apart = 0.0;  // the paths' largest distance (m)
  for (std::size_t k = 0; k < path[0].size(); ++k) apart = std::max(apart, (path[0][k] - path[1][k]).length());
  EXPECT_LT(apart, 1e-3);
  EXPECT_GT(path[0].back().x(), 0.0);  // it rolled over the field
}

// Case: a compact mesh of more triangles than Bullet's quantized tree can
// number in one part (2^21): TerrainObject gives it to Bullet in parts
// (kMeshPartTriangles), and a contact on a triangle past the first part
// names its prism. Before the parts, Bullet crashed on such a mesh.
TEST(BulletCompactMeshTest, AMeshOfMoreTrianglesThanOneBulletPartCollidesAndNamesItsPrisms) {
  testing::RandomGrid grid{.spacing_x = 0.1, .spacing_y = 0.1, .origin = {0.0, 0.0, 0.0}, .base_depth = 0.2};
  const Heightfield field = testing::randomHeightfield(1001, 1101, 0.01, 5, grid);  // 2.2e6 triangles
  TerrainBuilder builder;
  const PieceRange range =
      addTriangleMesh(builder, surfaceMesh(field), builder.addMaterial({}), {.thickness = 0.2, .compact = true}).pieces;
  ASSERT_GT(range.count, bullet::kMeshPartTriangles);
  const Terrain terrain = std::move(builder).build();
  BulletWorld w(terrain, ContactMode::kForce);
  SphereProbe probe(w);
  NamesItsPrism check = namesItsPrism(w, terrain, range.first + bullet::kMeshPartTriangles);
  std::mt19937 gen(13);
  for (int k = 0; k < 100; ++k) {
    // The last rows of cells: triangles 2^21 and beyond.
    const double x = 0.5 + (gen() / 4294967296.0) * 109.0, y = 96.0 + (gen() / 4294967296.0) * 3.5;
    probe.press(x, y, *surfaceHeight(field, x, y) + 0.04, check);
  }
  EXPECT_GE(check.contacts, 100);
  EXPECT_EQ(check.far, check.contacts);
}

// Case: a compact field of many tiles (kFieldTileCells cells a side, the
// last ones cut short): a contact on any tile names the prism under it, the
// tile's first row and column added to Bullet's numbers.
TEST(BulletCompactFieldTest, AContactOnAnyTileNamesItsPrism) {
  testing::RandomGrid grid{.spacing_x = 0.05, .spacing_y = 0.04, .origin = {1.0, -2.0, 0.3}, .base_depth = 0.2};
  const Heightfield field =
      testing::randomHeightfield(2 * bullet::kFieldTileCells + 20, 3 * bullet::kFieldTileCells + 7, 0.02, 17, grid);
  TerrainBuilder builder;
  const PieceRange range = addCompactHeightfield(builder, field, builder.addMaterial({}));
  const Terrain terrain = std::move(builder).build();
  BulletWorld w(terrain, ContactMode::kForce);
  SphereProbe probe(w);
  // Beyond the first tile's rows and columns.
  NamesItsPrism check = namesItsPrism(
      w, terrain, range.first + 2 * (bullet::kFieldTileCells * (field.cols - 1) + bullet::kFieldTileCells));
  std::mt19937 gen(19);
  for (int k = 0; k < 200; ++k) {
    const double x = 1.1 + (gen() / 4294967296.0) * (field.cols - 3) * grid.spacing_x;
    const double y = -1.9 + (gen() / 4294967296.0) * (field.rows - 3) * grid.spacing_y;
    probe.press(x, y, *surfaceHeight(field, x, y) + 0.04, check);
  }
  EXPECT_GE(check.contacts, 200);
  EXPECT_GT(check.far, check.contacts / 2);  // most on tiles past the first
}

// Every contact of every manifold in `w`, in Bullet's order.
std::vector<btManifoldPoint> manifoldPoints(BulletWorld& w) {
  std::vector<btManifoldPoint> points;
  for (int m = 0; m < w.dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = w.dispatcher.getManifoldByIndexInternal(m);
    for (int k = 0; k < manifold->getNumContacts(); ++k) points.push_back(manifold->getContactPoint(k));
  }
  return points;
}

// Case: a body meets a compact field's tiles through the plugin's own
// algorithm (field_body_algorithm.hpp: the body's box tested before
// Bullet's GJK on each triangle), and gets exactly the contacts Bullet's own
// convex-concave algorithm gives: the same points, normals, depths and
// triangles, bit for bit. Bodies of every convex kind the vehicles use,
// among them the robot's arm and a crossbar thinner than Bullet's 4 cm box
// margin, at random poses across a 1 cm field with a 0.3 m step.
TEST(BulletCompactFieldTest, ABodyMeetsTheFieldAsBulletsOwnAlgorithmWould) {
  testing::RandomGrid grid{.spacing_x = 0.01, .spacing_y = 0.01, .origin = {0.0, 0.0, 0.0}, .base_depth = 0.2};
  Heightfield field = testing::randomHeightfield(90, 2 * bullet::kFieldTileCells + 10, 0.005, 23, grid);
  for (int r = 0; r < field.rows; ++r) {
    for (int c = bullet::kFieldTileCells + 3; c < field.cols; ++c) field.heights[r * field.cols + c] += 0.3;
  }
  TerrainBuilder builder;
  addCompactHeightfield(builder, field, builder.addMaterial({}));
  const Terrain terrain = std::move(builder).build();
  BulletWorld plugin_world(terrain, ContactMode::kForce), bullet_world(terrain, ContactMode::kForce);
  // Bullet's own algorithm back in the second world, for every convex kind.
  for (int type = 0; type < CONCAVE_SHAPES_START_HERE; ++type) {
    if (type == CUSTOM_CONVEX_SHAPE_TYPE || !btBroadphaseProxy::isConvex(type)) continue;
    bullet_world.dispatcher.registerCollisionCreateFunc(
        type, TERRAIN_SHAPE_PROXYTYPE,
        bullet_world.config.getCollisionAlgorithmCreateFunc(type, TERRAIN_SHAPE_PROXYTYPE));
    bullet_world.dispatcher.registerCollisionCreateFunc(
        TERRAIN_SHAPE_PROXYTYPE, type,
        bullet_world.config.getCollisionAlgorithmCreateFunc(TERRAIN_SHAPE_PROXYTYPE, type));
  }
  btBoxShape arm(btVector3(0.215, 0.04, 0.04)), crossbar(btVector3(0.06, 0.22, 0.03)),
      chassis(btVector3(0.14, 0.2, 0.11));
  btCylinderShapeX cylinder(btVector3(0.05, 0.1, 0.1));
  btSphereShape ball(0.07);
  btConvexHullShape hull;
  for (const btVector3& p : {btVector3(-0.1, -0.05, -0.03), btVector3(0.12, -0.04, -0.03), btVector3(0.0, 0.08, -0.02),
                             btVector3(0.02, 0.0, 0.06), btVector3(-0.05, 0.03, 0.05)}) {
    hull.addPoint(p);
  }
  // The plugin's world creates its own algorithm for a body against a tile,
  // the other Bullet's.
  std::vector<const btCollisionShape*> shapes;
  leaves(*plugin_world.plugin->terrainObject().getCollisionShape(), shapes);
  const btCollisionShape* tile = shapes.front();
  ASSERT_EQ(tile->getShapeType(), TERRAIN_SHAPE_PROXYTYPE);
  btCollisionObject probe;
  probe.setCollisionShape(&arm);
  const btCollisionObjectWrapper probe_wrap(nullptr, &arm, &probe, btTransform::getIdentity(), -1, -1);
  const btCollisionObjectWrapper tile_wrap(nullptr, tile, &plugin_world.plugin->terrainObject(),
                                           btTransform::getIdentity(), -1, -1);
  for (BulletWorld* w : {&plugin_world, &bullet_world}) {
    btCollisionAlgorithm* algorithm =
        w->dispatcher.findAlgorithm(&probe_wrap, &tile_wrap, nullptr, BT_CONTACT_POINT_ALGORITHMS);
    EXPECT_EQ(dynamic_cast<btConvexConcaveCollisionAlgorithm*>(algorithm) == nullptr, w == &plugin_world);
    algorithm->~btCollisionAlgorithm();
    w->dispatcher.freeCollisionAlgorithm(algorithm);
  }

  std::mt19937 gen(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int contacts = 0;
  for (btConvexShape* shape :
       std::initializer_list<btConvexShape*>{&arm, &crossbar, &chassis, &cylinder, &ball, &hull}) {
    btCollisionObject body[2];
    BulletWorld* worlds[2] = {&plugin_world, &bullet_world};
    for (int k = 0; k < 2; ++k) {
      body[k].setCollisionShape(shape);
      worlds[k]->world.addCollisionObject(&body[k], btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    }
    for (int pose = 0; pose < 60; ++pose) {
      // Anywhere over the field, across the step too, from 5 cm above the
      // ground to 5 cm into it, turned at random.
      const double x = 0.15 + unit(gen) * (field.cols - 31) * grid.spacing_x;
      const double y = 0.15 + unit(gen) * (field.rows - 31) * grid.spacing_y;
      const double z = *surfaceHeight(field, x, y) + 0.1 * (unit(gen) - 0.5);
      const btQuaternion turn(btVector3(unit(gen) - 0.5, unit(gen) - 0.5, unit(gen) - 0.5), 2.0 * M_PI * unit(gen));
      for (int k = 0; k < 2; ++k) {
        body[k].setWorldTransform(btTransform(turn, btVector3(x, y, z)));
        worlds[k]->world.performDiscreteCollisionDetection();
      }
      const std::vector<btManifoldPoint> ours = manifoldPoints(plugin_world), bullets = manifoldPoints(bullet_world);
      ASSERT_EQ(ours.size(), bullets.size()) << "shape " << shape->getName() << ", pose " << pose;
      for (std::size_t p = 0; p < ours.size(); ++p) {
        EXPECT_EQ(ours[p].getPositionWorldOnA(), bullets[p].getPositionWorldOnA());
        EXPECT_EQ(ours[p].getPositionWorldOnB(), bullets[p].getPositionWorldOnB());
        EXPECT_EQ(ours[p].m_normalWorldOnB, bullets[p].m_normalWorldOnB);
        EXPECT_EQ(ours[p].getDistance(), bullets[p].getDistance());
        EXPECT_EQ(ours[p].m_partId1, bullets[p].m_partId1);
        EXPECT_EQ(ours[p].m_index1, bullets[p].m_index1);
      }
      contacts += static_cast<int>(ours.size());
    }
    for (int k = 0; k < 2; ++k) worlds[k]->world.removeCollisionObject(&body[k]);
  }
  EXPECT_GT(contacts, 500);  // the bodies did meet the field
}

INSTANTIATE_TEST_SUITE_P(Parts, BulletCompactTerrainTest,
                         ::testing::Values(testing::CompactPart::kField, testing::CompactPart::kMesh,
                                           testing::CompactPart::kFieldWithHoles),
                         [](const ::testing::TestParamInfo<testing::CompactPart>& info) {
                           return testing::nameOf(info.param);
                         });

}  // namespace
}  // namespace wtc
