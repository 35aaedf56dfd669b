package org.robotrun.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.world.CellEditor.NumberField;
import org.robotrun.world.CellEditor.Result;

/** The cell editor's model, without a window: add, edit, parent, delete, undo, scenarios, bad input. */
class CellEditorTest {
  private static final CellEditor.MeshLoader ONE_TRIANGLE = (file, scale) -> {
    if (file.toString().contains("broken")) {
      throw new IllegalArgumentException("line 3: expected 'facet normal'");
    }
    return new TriangleMesh(new float[] {0, 0, 0, (float) scale, 0, 0, 0, (float) scale, 0});
  };

  private static Scenario cell(WorldObject... objects) {
    RobotSetup robot = new RobotSetup("robot1", "lrmate200id", Transform.IDENTITY, EndEffectorType.FACEPLATE, List.of(0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
    return new Scenario("lab", "Move the part.", List.of(robot), new World(List.of(objects)), List.of(), Optional.empty(),
        new TreeMap<>(), new TreeMap<>(), new TreeMap<>(), Optional.empty());
  }

  private static WorldObject table() {
    return WorldObject.of("table", ObjectKind.FIXTURE, new Shape.Box(400, 700, 230), Rgb.GREY, Transform.translation(420, 0, -330), Optional.empty());
  }

  private final CellEditor ed = new CellEditor(cell(table()), ONE_TRIANGLE);

  private static String refusal(Result r) {
    assertThat(r).isInstanceOf(Result.Refused.class);
    return ((Result.Refused) r).message();
  }

  @Test
  void aNewObjectStandsClearOfTheRobotAndOfEveryOtherObject() {
    // at the cell origin it would stand inside the robot's base (an instant collision alarm)
    for (int i = 0; i < 6; i++) {
      assertThat(i % 2 == 0 ? ed.addBox() : ed.addCylinder()).isInstanceOf(Result.Done.class);
    }
    World w = ed.world();
    for (WorldObject o : w.objects()) {
      if (o.name().equals("table")) {
        continue;
      }
      var p = o.startPose().translationVector();
      assertThat(Math.hypot(p.x(), p.y())).as(o.name() + " from the robot's axis").isGreaterThanOrEqualTo(450);
      assertThat(p.z()).as(o.name() + " stands on the floor").isEqualTo(50);
      for (WorldObject other : w.objects()) {
        if (other != o) {
          assertThat(w.collisionBox(o.name()).overlaps(w.collisionBox(other.name()))).as(o.name() + " vs " + other.name())
              .isFalse();
        }
      }
    }
  }

  @Test
  void addedBoxesGetFreeNamesAndAreParts() {
    assertThat(ed.addBox()).isInstanceOf(Result.Done.class);
    assertThat(ed.addBox()).isInstanceOf(Result.Done.class);
    assertThat(ed.addCylinder()).isInstanceOf(Result.Done.class);
    assertThat(ed.world().objects()).extracting(WorldObject::name).containsExactly("table", "box1", "box2", "cylinder1");
    assertThat(ed.world().find("box1").orElseThrow().kind()).isEqualTo(ObjectKind.PART);
  }

  @Test
  void numberFieldsSetThePoseAndTheSize() {
    ed.addBox();
    assertThat(ed.setNumber("box1", NumberField.X, "250.5")).isInstanceOf(Result.Done.class);
    assertThat(ed.setNumber("box1", NumberField.R, "90")).isInstanceOf(Result.Done.class);
    assertThat(ed.setNumber("box1", NumberField.HEIGHT, "40")).isInstanceOf(Result.Done.class);
    // tolerance 1e-9 mm / deg: one XYZWPR round trip
    assertThat(ed.number("box1", NumberField.X)).isCloseTo(250.5, within(1e-9));
    assertThat(ed.number("box1", NumberField.R)).isCloseTo(90, within(1e-9));
    assertThat(ed.world().find("box1").orElseThrow().shape()).isEqualTo(new Shape.Box(100, 100, 40));
  }

  @Test
  void nonsenseInANumberFieldIsRefusedNamingTheFieldAndRangeAndTheOldValueStays() {
    ed.addBox();
    ed.setNumber("box1", NumberField.X, 10);
    for (String bad : List.of("abc", "NaN", "Infinity", "", "12f")) {
      assertThat(refusal(ed.setNumber("box1", NumberField.X, bad)))
          .isEqualTo("X '" + bad + "': not a number, enter -100000 to 100000 mm; X stays 10 mm");
    }
    // worded as the controller's "Value out of range", with the value the field keeps
    assertThat(refusal(ed.setNumber("box1", NumberField.X, "100001")))
        .isEqualTo("X 100001: Value out of range, enter -100000 to 100000 mm; X stays 10 mm");
    assertThat(refusal(ed.setNumber("box1", NumberField.X, "1e308"))).startsWith("X ").contains("Value out of range");
    assertThat(refusal(ed.setNumber("box1", NumberField.LENGTH, "-5")))
        .isEqualTo("length -5: Value out of range, enter more than 0, at most 100000 mm; length stays 100 mm");
    assertThat(refusal(ed.setNumber("box1", NumberField.HEIGHT, "0"))).contains("height");
    assertThat(refusal(ed.setNumber("box1", NumberField.W, "400"))).contains("W").contains("deg");
    assertThat(refusal(ed.setNumber("box1", NumberField.RADIUS, "5"))).contains("a box has length, width and height");
    assertThat(ed.number("box1", NumberField.X)).isEqualTo(10);
    assertThat(ed.world().find("box1").orElseThrow().shape()).isEqualTo(new Shape.Box(100, 100, 100));
  }

  @Test
  void parentingKeepsTheObjectWhereItIsInTheCellAndRefusesALoop() {
    ed.addBox();
    ed.setNumber("box1", NumberField.X, 500);
    ed.setKind("box1", ObjectKind.FIXTURE);
    assertThat(ed.setParent("box1", Optional.of("table"))).isInstanceOf(Result.Done.class);
    // tolerance 1e-9 mm: composition of two translations
    assertThat(ed.world().poseInCell("box1").x()).isCloseTo(500, within(1e-9));
    assertThat(ed.number("box1", NumberField.X)).isCloseTo(80, within(1e-9));
    assertThat(refusal(ed.setParent("table", Optional.of("box1")))).startsWith("parent:").contains("loop");
    assertThat(refusal(ed.setParent("table", Optional.of("nothing")))).startsWith("parent: no fixture named");
    ed.addCylinder();
    assertThat(refusal(ed.setParent("box1", Optional.of("cylinder1")))).contains("expected a fixture");
    assertThat(refusal(ed.setKind("table", ObjectKind.PART))).startsWith("kind:");
    assertThat(ed.world().find("table").orElseThrow().startParent()).isEmpty();
  }

  @Test
  void deleteRefusesAFixtureWithObjectsOnItAndRenameCarriesTheChildren() {
    ed.addBox();
    ed.setParent("box1", Optional.of("table"));
    assertThat(refusal(ed.delete("table"))).contains("box1 stands on it");
    assertThat(ed.rename("table", "bench")).isInstanceOf(Result.Done.class);
    assertThat(ed.world().find("box1").orElseThrow().startParent()).contains("bench");
    assertThat(refusal(ed.rename("box1", "bench"))).startsWith("name: 'bench' is already taken");
    assertThat(refusal(ed.rename("box1", "has space"))).startsWith("name: expected");
    assertThat(ed.delete("box1")).isInstanceOf(Result.Done.class);
    assertThat(ed.delete("bench")).isInstanceOf(Result.Done.class);
    assertThat(ed.world().objects()).isEmpty();
  }

  @Test
  void undoAndRedoWalkBackAndForthThroughEdits() {
    World start = ed.world();
    ed.addBox();
    ed.setNumber("box1", NumberField.Z, 30);
    World edited = ed.world();
    ed.undo();
    ed.undo();
    assertThat(ed.world()).isEqualTo(start);
    assertThat(refusal(ed.undo())).isEqualTo("nothing to undo");
    ed.redo();
    ed.redo();
    assertThat(ed.world()).isEqualTo(edited);
    ed.undo();
    ed.addCylinder();  // a new edit drops the redo branch
    assertThat(ed.canRedo()).isFalse();
  }

  @Test
  void undoAndRedoSayWhatTheyTookBackOrDidAgain() {
    Result set = ed.addBox();
    Result z = ed.setNumber("box1", NumberField.Z, 30);
    String zDone = ((Result.Done) z).message();
    assertThat(((Result.Done) ed.undo()).message()).isEqualTo("undone: " + zDone);
    assertThat(((Result.Done) ed.undo()).message()).isEqualTo("undone: " + ((Result.Done) set).message());
    assertThat(((Result.Done) ed.redo()).message()).isEqualTo("redone: " + ((Result.Done) set).message());
    assertThat(((Result.Done) ed.redo()).message()).isEqualTo("redone: " + zDone);
  }

  @Test
  void aRefusedEditLeavesNothingToUndo() {
    ed.setNumber("table", NumberField.X, "oops");
    assertThat(ed.canUndo()).isFalse();
  }

  @Test
  void duplicateCopiesShapeColourAndParentBesideTheOriginal() {
    ed.addBox();
    ed.setColour("box1", "#102030");
    ed.setParent("box1", Optional.of("table"));
    assertThat(ed.duplicate("box1")).isInstanceOf(Result.Done.class);
    WorldObject copy = ed.world().find("box1_copy1").orElseThrow();
    assertThat(copy.colour().hex()).isEqualTo("#102030");
    assertThat(copy.startParent()).contains("table");
    assertThat(ed.number("box1_copy1", NumberField.Y) - ed.number("box1", NumberField.Y)).isCloseTo(100, within(1e-9));
    assertThat(refusal(ed.setColour("box1", "red"))).startsWith("colour: expected #rrggbb");
  }

  @Test
  void stlMeshesAreRefusedWhenTheFileIsNotOne() {
    assertThat(refusal(ed.addMesh(Path.of("part.obj"), 1))).startsWith("STL file: expected a file ending in .stl");
    assertThat(refusal(ed.addMesh(Path.of("broken.stl"), 1))).startsWith("STL file broken.stl: line 3");
    assertThat(refusal(ed.addMesh(Path.of("ok.stl"), -1))).isEqualTo("scale -1: Value out of range, enter more than 0, at most 10000");
    assertThat(ed.addMesh(Path.of("bracket.stl"), 1000)).isInstanceOf(Result.Done.class);
    // an import confirms what it made, from the file it read
    assertThat(((Result.Done) ed.addMesh(Path.of("bracket.stl"), 1000)).message())
        .startsWith("imported bracket.stl as fixture bracket").contains(" triangles, scale 1000)");
    assertThat(ed.world().find("bracket1").orElseThrow().shape()).isInstanceOf(Shape.Mesh.class);
    assertThat(ed.number("bracket1", NumberField.SCALE)).isEqualTo(1000);
  }

  @Test
  void scenariosAreNamedOneIsActiveAndEditsStayInTheirOwn() {
    assertThat(ed.addScenario("with box")).isInstanceOf(Result.Done.class);
    assertThat(ed.activeIndex()).isEqualTo(1);
    ed.addBox();
    ed.activate(0);
    assertThat(ed.world().find("box1")).isEmpty();
    ed.activate(1);
    assertThat(ed.world().find("box1")).isPresent();
    assertThat(refusal(ed.addScenario("lab"))).contains("already taken");
    assertThat(ed.deleteActiveScenario()).isInstanceOf(Result.Done.class);
    assertThat(refusal(ed.deleteActiveScenario())).isEqualTo("cannot delete the only scenario");
    assertThat(ed.active().name()).isEqualTo("lab");
  }
}
