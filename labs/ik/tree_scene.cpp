// IK lab, scene "tree": several effectors on one skeleton (Workbook §2.1 task 5, §2.7; IK slides,
// "Multiple end effectors"): a hand reaching with five finger tips, or Buss & Kim's "double Y".
#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

enum class TreeShape { Hand, DoubleY };
constexpr auto kTreeShapeNames = enumNames<TreeShape>({{TreeShape::Hand, "hand"}, {TreeShape::DoubleY, "double-y"}});

class TreeScene final : public IkScene {
 public:
  TreeScene() {
    options_.solver = SolverKind::SelectivelyDamped;
    options_.maxIterations = 30;
    // FABRIK on the hand's one-way fingers needs our two options (docs/performance-ik.md): on here,
    // the panel turns them off to show the published passes.
    options_.fabrikHingeTwist = true;
    options_.fabrikLimitFit = true;
    declareSolverParams();
    params_
        .choiceEnum("shape", &shape_, kTreeShapeNames,
                    "The tree: a hand with five finger tips, or Buss & Kim's double Y.")
        .needsReset();
  }
  std::string description() const override {
    return "Several goals on one tree: the Jacobian stacks one 3-row block per effector and SDLS damps each singular "
           "direction by itself (IK-8); FABRIK averages at sub-bases.";
  }

 protected:
  Rig build() const override { return shape_ == TreeShape::Hand ? buildHand().value() : buildDoubleY().value(); }
  Real pathRadius() const override { return shape_ == TreeShape::Hand ? 0.03 : 0.3; }

 private:
  TreeShape shape_ = TreeShape::DoubleY;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Trees", "tree", pba::lab::TreeScene);
