// The ground plane's material textures and bump maps: mapped like a plane
// primitive facing +y at the world's origin, so the texture is fixed to the
// floor wherever the camera is; a ground without them compiles as before.

#include <algorithm>

#include <gtest/gtest.h>

#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene.h"

namespace sdfwb {
namespace {

using glm::dvec3;
using program::Opcode;

constexpr double kFloor = 0.25;

// A small sphere above a ground at height 0.25 whose material is `floor`: the
// middle of a row of checker cubes of side 0.5 (at a cube boundary a solid
// checker is the mean of its colours).
scene::Scene groundScene(const scene::Material& floor) {
    scene::Scene s;
    scene::Node translate = scene::Node::make(scene::NodeKind::Translate);
    translate.set("offset", dvec3(0, 1, 0));
    translate.children.push_back(scene::Node::make(scene::NodeKind::Sphere));
    s.root = translate;
    s.materials.push_back(floor);
    s.environment.ground.enabled = true;
    s.environment.ground.material = floor.name;
    s.environment.ground.pattern = scene::GroundPattern::Plain;
    s.environment.ground.height = kFloor;
    return s;
}

scene::Material checkerFloor() {
    scene::Material m = scene::defaultMaterial();
    m.name = "floor";
    m.diffuse = dvec3(0.9);
    m.texture = scene::TexturePattern::Checker;
    m.textureScale = 0.5;
    m.textureColor = dvec3(0.1);
    m.textureFiltering = false;  // a point sample: the same at every distance
    return m;
}

// The ground's diffuse colour at world points on the floor, seen from the scene's eye.
class FloorProbe {
public:
    explicit FloorProbe(const scene::Scene& s)
        : program_(program::compileScene(s)),
          kernel_(program_, cpu::f64::FieldSource::Whole),
          scratch_(program_),
          eye_(scene::cameraFrame(s.camera).eye) {}
    dvec3 diffuse(dvec3 world) { return dvec3(kernel_.map(scratch_, world - eye_).material.diffuse); }

private:
    program::Program program_;
    cpu::f64::Kernel kernel_;
    cpu::f64::Scratch scratch_;
    dvec3 eye_;
};

TEST(GroundTexture, ItsTextureStaysOnTheFloorAsTheCameraMoves) {
    scene::Scene near = groundScene(checkerFloor());
    scene::Scene far = near;
    far.camera.target = dvec3(40, 2, -25);
    far.camera.azimuth = 130;
    far.camera.distance = 9;
    FloorProbe fromNear(near), fromFar(far);
    int light = 0, dark = 0;
    for (double x = -1.9; x < 2; x += 0.37) {
        for (double z = -1.7; z < 2; z += 0.41) {
            dvec3 world(x, kFloor, z);
            dvec3 a = fromNear.diffuse(world), b = fromFar.diffuse(world);
            EXPECT_NEAR(a.x, b.x, 1e-9) << "at x " << x << ", z " << z;
            (a.x > 0.5 ? light : dark) += 1;
        }
    }
    // the checker shows: both colours, in about equal shares
    EXPECT_GT(std::min(light, dark), 30);
}

TEST(GroundTexture, ItsBumpMapAndTextureFollowTheGroundInstruction) {
    scene::Material floor = checkerFloor();
    floor.bump = scene::BumpPattern::Waves;
    program::Program program = program::compileScene(groundScene(floor));
    ASSERT_GE(program.groundStart, 0);
    std::vector<Opcode> ground;
    for (size_t i = static_cast<size_t>(program.groundStart); i < program.code.size(); ++i) {
        ground.push_back(program.code[i].op);
    }
    // the world point, the plane, its texture and bump map, then the union with the root
    EXPECT_EQ(ground,
              (std::vector<Opcode>{Opcode::Translate, Opcode::Ground, Opcode::Texture, Opcode::Bump, Opcode::Union}));
}

TEST(GroundTexture, AnUntexturedGroundCompilesAsBefore) {
    scene::Material floor = scene::defaultMaterial();
    floor.name = "floor";
    program::Program program = program::compileScene(groundScene(floor));
    ASSERT_EQ(program.groundStart, static_cast<int>(program.code.size()) - 2);
    EXPECT_EQ(program.code[static_cast<size_t>(program.groundStart)].op, Opcode::Ground);
    EXPECT_EQ(program.code.back().op, Opcode::Union);
}

}  // namespace
}  // namespace sdfwb
