package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;

/**
 * The controller's frame table as an R-30iB keeps it: UTOOL[1..10] and UFRAME[1..10] each with a
 * comment, number 0 the flange / WORLD (identity, read-only, selectable), the active numbers
 * 0..10, tool and user frames apart; JOGFRAME[1..5] with JOGFRAME 1 active at start.
 */
class FrameTableTest {
  private static final Transform A = Xyzwpr.ofDegrees(10, -20, 30, 90, 0, 45).toTransform();
  private static final Transform B = Xyzwpr.ofDegrees(-5, 6, 700, 0, -30, 0).toTransform();

  private static void assertSame(Transform got, Transform want) {
    Xyzwpr g = Xyzwpr.fromTransform(got);
    Xyzwpr w = Xyzwpr.fromTransform(want);
    assertThat(new double[] {g.x(), g.y(), g.z(), g.wDeg(), g.pDeg(), g.rDeg()})
        .containsExactly(new double[] {w.x(), w.y(), w.z(), w.wDeg(), w.pDeg(), w.rDeg()},
            org.assertj.core.data.Offset.offset(1e-9));
  }

  @Test
  void aNewTableIsAllIdentityWithNoCommentsAndFrameZeroActive() {
    FrameTable t = new FrameTable();
    for (FrameKind k : FrameKind.values()) {
      assertThat(t.active(k)).isZero();
      for (int n = 0; n <= FrameTable.COUNT; n++) {
        assertSame(t.transform(k, n), Transform.IDENTITY);
        assertThat(t.comment(k, n)).isEmpty();
      }
    }
    assertSame(t.activeTool(), Transform.IDENTITY);
    assertSame(t.activeUser(), Transform.IDENTITY);
    assertThat(t.activeJogNumber()).isEqualTo(1);
    assertSame(t.activeJogFrame(), Transform.IDENTITY);
  }

  @Test
  void toolAndUserFramesAreKeptApartAndTheActiveOnesFollowTheSelection() {
    FrameTable t = new FrameTable();
    t.setTransform(FrameKind.TOOL, 3, A);
    t.setTransform(FrameKind.USER, 3, B);
    t.setTransform(FrameKind.USER, FrameTable.COUNT, A);
    assertSame(t.transform(FrameKind.TOOL, 3), A);
    assertSame(t.transform(FrameKind.USER, 3), B);
    assertSame(t.transform(FrameKind.TOOL, FrameTable.COUNT), Transform.IDENTITY);
    assertSame(t.transform(FrameKind.USER, FrameTable.COUNT), A);
    // selecting is per kind
    t.select(FrameKind.TOOL, 3);
    assertThat(t.active(FrameKind.TOOL)).isEqualTo(3);
    assertThat(t.active(FrameKind.USER)).isZero();
    assertSame(t.activeTool(), A);
    assertSame(t.activeUser(), Transform.IDENTITY);
    t.select(FrameKind.USER, FrameTable.COUNT);
    assertSame(t.activeUser(), A);
    assertSame(t.activeTool(), A);
    t.select(FrameKind.USER, 3);
    assertSame(t.activeUser(), B);
    // back to frame 0: flange / WORLD
    t.select(FrameKind.TOOL, 0);
    assertSame(t.activeTool(), Transform.IDENTITY);
    // comments per kind and number
    t.setComment(FrameKind.TOOL, 3, "gripper");
    t.setComment(FrameKind.USER, 3, "table");
    assertThat(t.comment(FrameKind.TOOL, 3)).isEqualTo("gripper");
    assertThat(t.comment(FrameKind.USER, 3)).isEqualTo("table");
    assertThat(t.comment(FrameKind.TOOL, 4)).isEmpty();
  }

  @Test
  void framesAreReadAndSetInPendantUnits() {
    FrameTable t = new FrameTable();
    Position.Cartesian p = Position.Cartesian.of(Xyzwpr.ofDegrees(100, -50, 25, 0, 90, -90), Config.DEFAULT);
    t.setPosition(FrameKind.USER, 2, p);
    Xyzwpr back = t.position(FrameKind.USER, 2).toXyzwpr();
    Xyzwpr want = Xyzwpr.fromTransform(Xyzwpr.ofDegrees(100, -50, 25, 0, 90, -90).toTransform());
    assertThat(back.x()).isCloseTo(100, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(back.y()).isCloseTo(-50, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(back.z()).isCloseTo(25, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(back.pDeg()).isCloseTo(want.pDeg(), org.assertj.core.data.Offset.offset(1e-9));
    assertThat(t.position(FrameKind.TOOL, 2).toXyzwpr().z()).isZero();
    t.setJogFrame(5, p);
    assertThat(t.jogFrame(5).toXyzwpr().x()).isCloseTo(100, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(t.jogFrame(1).toXyzwpr().x()).isZero();
    t.selectJogFrame(5);
    assertThat(t.activeJogNumber()).isEqualTo(5);
    assertSame(t.activeJogFrame(), Xyzwpr.ofDegrees(100, -50, 25, 0, 90, -90).toTransform());
  }

  @Test
  void numbersOutsideTheTableAreRefusedAndFrameZeroCannotBeEdited() {
    FrameTable t = new FrameTable();
    for (FrameKind k : FrameKind.values()) {
      // 0..10 may be read and selected
      t.select(k, 0);
      t.select(k, FrameTable.COUNT);
      t.comment(k, 0);
      assertThatThrownBy(() -> t.select(k, -1)).isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("0..10").hasMessageContaining("-1");
      assertThatThrownBy(() -> t.select(k, FrameTable.COUNT + 1)).isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("11");
      assertThatThrownBy(() -> t.transform(k, FrameTable.COUNT + 1)).isInstanceOf(IllegalArgumentException.class);
      assertThatThrownBy(() -> t.comment(k, -1)).isInstanceOf(IllegalArgumentException.class);
      // 1..10 may be set: 0 is the flange / WORLD
      t.setTransform(k, 1, A);
      t.setComment(k, FrameTable.COUNT, "last");
      assertThatThrownBy(() -> t.setTransform(k, 0, A)).isInstanceOf(IllegalArgumentException.class)
          .hasMessageContaining("1..10");
      assertThatThrownBy(() -> t.setComment(k, 0, "x")).isInstanceOf(IllegalArgumentException.class);
      assertThatThrownBy(() -> t.setTransform(k, FrameTable.COUNT + 1, A)).isInstanceOf(IllegalArgumentException.class);
      assertSame(t.transform(k, 0), Transform.IDENTITY);
    }
    // jog frames 1..5
    t.selectJogFrame(1);
    t.selectJogFrame(FrameTable.JOG_COUNT);
    assertThatThrownBy(() -> t.selectJogFrame(0)).isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("1..5");
    assertThatThrownBy(() -> t.selectJogFrame(6)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> t.jogFrame(0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> t.setJogFrame(6, Position.Cartesian.of(Xyzwpr.ofDegrees(0, 0, 0, 0, 0, 0), Config.DEFAULT)))
        .isInstanceOf(IllegalArgumentException.class);
  }
}
