package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Body;
import org.robotrun.collision.BodyKind;
import org.robotrun.collision.BodyPair;
import org.robotrun.collision.PairFilter;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.math.Transform;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Rgb;
import org.robotrun.world.Scenario;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * Which body pairs are checked, by body kind and link, as docs/collision.md states (issue 31): the
 * expected answer of every pair is written here from the document's rules, for the collision
 * package's {@link StandardPairFilter} (links at least two apart) and the simulation's
 * {@link CellPairFilter} (at least three), both ways round; and a real cell shows that the J1
 * housing (link 1) is checked against a fixture while the base (link 0) is not.
 */
class CollisionPairTruthTableTest {
  static final List<Body> ROBOT1 = links("robot1");
  static final List<Body> ROBOT2 = links("robot2");
  static final Body TABLE = Body.fixture("table", "table");
  static final Body TABLE_LEG = Body.fixture("table", "table#2");
  static final Body JIG = Body.fixture("jig", "jig");
  static final Body HELD1 = Body.part("part1", "part1"); // held by robot1
  static final Body HELD2 = Body.part("part2", "part2"); // held by robot2
  static final Body LOOSE = Body.part("part3", "part3"); // at rest
  static final Body LOOSE_B = Body.part("part4", "part4"); // at rest
  static final Map<String, String> HELD = Map.of("part1", "robot1", "part2", "robot2");

  static List<Body> links(String robot) {
    List<Body> out = new ArrayList<>();
    for (int l = 0; l <= Body.TOOL_LINK; l++) {
      out.add(Body.robotLink(robot, l, robot + "/link" + l));
    }
    return out;
  }

  /** docs/collision.md, "Standard rules" and "What the simulation decided", with the self-collision gap. */
  static boolean expected(Body a, Body b, int selfGap) {
    if (a.owner().equals(b.owner())) {
      // Same robot: links at least selfGap apart; boxes of one fixture or part: never.
      return a.kind() == BodyKind.ROBOT && Math.abs(a.link() - b.link()) >= selfGap;
    }
    if (a.kind() != BodyKind.ROBOT && b.kind() == BodyKind.ROBOT) {
      return expected(b, a, selfGap);
    }
    if (a.kind() == BodyKind.ROBOT) {
      return switch (b.kind()) {
        case ROBOT -> true; // another robot: every link
        case FIXTURE -> a.link() != 0; // the base stands on a fixture; link 1 (the J1 housing) and up are checked
        case PART -> !a.owner().equals(HELD.get(b.owner())); // not against the part it holds
      };
    }
    // Objects at rest are never checked against each other; a held part against everything else.
    return HELD.containsKey(a.owner()) || HELD.containsKey(b.owner());
  }

  static List<Body> everyBody() {
    List<Body> all = new ArrayList<>(ROBOT1);
    all.addAll(ROBOT2);
    all.addAll(List.of(TABLE, TABLE_LEG, JIG, HELD1, HELD2, LOOSE, LOOSE_B));
    return all;
  }

  static void checkTable(PairFilter filter, int selfGap) {
    List<Body> all = everyBody();
    int checked = 0;
    for (Body a : all) {
      for (Body b : all) {
        if (a == b) {
          continue;
        }
        boolean want = expected(a, b, selfGap);
        assertThat(filter.mayCollide(a, b)).as("%s vs %s", a.name(), b.name()).isEqualTo(want);
        checked += want ? 1 : 0;
      }
    }
    assertThat(checked).isGreaterThan(100);
  }

  @Test
  void standardRulesPairByPair() {
    checkTable(new StandardPairFilter(HELD), 2);
  }

  @Test
  void cellRulesPairByPair() {
    checkTable(new CellPairFilter(new StandardPairFilter(HELD)), CellPairFilter.SELF_LINK_GAP);
    assertThat(CellPairFilter.SELF_LINK_GAP).as("docs/collision.md: links at least three apart").isEqualTo(3);
  }

  @Test
  void allowedContactsAreNeverReportedWhateverTheKind() {
    Set<BodyPair> allowed = Set.of(BodyPair.of(ROBOT1.get(2), ROBOT1.get(5)), BodyPair.of(ROBOT1.get(3), TABLE),
        BodyPair.of(HELD1, JIG));
    StandardPairFilter standard = new StandardPairFilter(HELD, allowed);
    for (PairFilter f : List.of(standard, new CellPairFilter(standard))) {
      assertThat(f.mayCollide(ROBOT1.get(2), ROBOT1.get(5))).isFalse();
      assertThat(f.mayCollide(ROBOT1.get(5), ROBOT1.get(2))).isFalse();
      assertThat(f.mayCollide(TABLE, ROBOT1.get(3))).isFalse();
      assertThat(f.mayCollide(JIG, HELD1)).isFalse();
      // their neighbours in the table still are
      assertThat(f.mayCollide(ROBOT1.get(2), ROBOT1.get(6))).isTrue();
      assertThat(f.mayCollide(ROBOT1.get(4), TABLE)).isTrue();
      assertThat(f.mayCollide(HELD1, TABLE)).isTrue();
    }
  }

  /** A robot at the cell origin (base 330 mm below WORLD) beside a 60 mm block; the block's pose is its bottom face centre. */
  static Simulation cellWithBlock(double x, double y, double zBottom, double height) {
    RobotSetup robot = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.FACEPLATE,
        List.of(0.0, 0.0, 0.0, 0.0, -Math.PI / 2, 0.0));
    WorldObject block = WorldObject.of("block", ObjectKind.FIXTURE, new Shape.Box(60, 60, height), Rgb.GREY,
        Transform.translation(x, y, zBottom), Optional.empty());
    TreeMap<Integer, Transform> user = new TreeMap<>();
    user.put(1, Transform.IDENTITY);
    Scenario sc = new Scenario("block", "", List.of(robot), new World(List.of(block)), List.of(), Optional.empty(),
        new TreeMap<>(), new TreeMap<>(), user, Optional.empty());
    return CellRig.cell(sc);
  }

  static final String J1_TO_90 = """
      /PROG  SWING
      /ATTR
      /MN
         1:J P[1] 20% FINE ;
      /POS
      P[1]{
         GP1:
      	UF : 1, UT : 1,
      	J1=    90.000 deg,	J2=     0.000 deg,	J3=     0.000 deg,
      	J4=     0.000 deg,	J5=   -90.000 deg,	J6=     0.000 deg
      };
      /END
      """;

  @Test
  void theJ1HousingHitsAFixtureTheBaseDoesNot() {
    // Link 1 carries the J2 housing, a cylinder about the link's y axis 62 mm in radius reaching x = 112 mm from
    // the J1 axis at 268..392 mm above the base (resources/robots/lrmate200id.json). A block at y = 100..160,
    // 280..330 mm above the base is clear of it at J1 = 0 and in its way when J1 turns to +90°; the upper arm
    // (link 2, from 345 mm up) and the base (link 0, up to 240 mm) pass it. Base 330 mm below WORLD: z = -50..0.
    Simulation sim = cellWithBlock(0, 130, -50, 50);
    Controller c = sim.controllers().get(0);
    c.saveProgram(org.robotrun.io.LsReader.parse("SWING.LS", J1_TO_90).program());
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "SWING", 20, s -> {});
    assertThat(r.alarm()).as("J1 turning link 1 into the block").isPresent();
    assertThat(r.alarm().get().code()).isEqualTo(Simulation.COLLISION_ALARM);
    assertThat(sim.collisionEvents()).extracting(e -> new java.util.TreeSet<>(List.of(e.bodyA(), e.bodyB())).first())
        .allSatisfy(n -> assertThat(n).startsWith("block"));
    assertThat(sim.collisionEvents()).extracting(e -> e.bodyA() + "|" + e.bodyB())
        .allSatisfy(s -> assertThat(s).contains("robot1/link1"));

    // The same block around the base column (link 0: a 220 mm plate and an 85 mm column up to 240 mm): no alarm.
    Simulation base = cellWithBlock(0, 100, -330, 150);
    Controller cb = base.controllers().get(0);
    cb.saveProgram(org.robotrun.io.LsReader.parse("SWING.LS", J1_TO_90).program());
    HeadlessRun.Result rb = HeadlessRun.run(base, cb, "SWING", 20, s -> {});
    assertThat(rb.alarm()).as("a fixture touching only the base").isEmpty();
  }
}
