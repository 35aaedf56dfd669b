package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The controller's safety rules through key scripts on {@code robotrun pendant} with the real
 * controller, checked on the per-tick CSV trace ({@code --trace}): T1 speed cap, hold-to-run,
 * SRVO-003, E-stop, AUTO and CYCLE START.
 */
class PendantSafetyTest {
  /** Trace columns: time, J1..J6, TCP x y z w p r, flange fx fy fz. */
  private static final int TCP_X = 7;
  private static final int FLANGE_X = 13;
  private static final double TICK_SEC = 0.004;
  /** Trace positions carry 4 decimals (mm): speeds from them are good to 2 × 0.5e-4 mm per tick. */
  private static final double ROUNDING_MM_PER_SEC = 1e-4 / TICK_SEC;

  /** A fast straight move (2000 mm/s) and a full-speed joint move, both far enough to reach speed. */
  private static final String PROGRAM = """
      /PROG  FAST
      /ATTR
      /MN
         1:J P[1] 100% FINE ;
         2:L P[2] 2000mm/sec FINE ;
         3:J P[3] 100% FINE ;
      /POS
      P[1]{
         GP1:
      \tUF : 1, UT : 1,
      \tJ1= 0.000 deg,\tJ2= 0.000 deg,\tJ3= 0.000 deg,
      \tJ4= 0.000 deg,\tJ5= -90.000 deg,\tJ6= 0.000 deg
      };
      P[2]{
         GP1:
      \tUF : 1, UT : 1,
      \tJ1= 60.000 deg,\tJ2= 20.000 deg,\tJ3= -10.000 deg,
      \tJ4= 0.000 deg,\tJ5= -80.000 deg,\tJ6= 0.000 deg
      };
      P[3]{
         GP1:
      \tUF : 1, UT : 1,
      \tJ1= -60.000 deg,\tJ2= 30.000 deg,\tJ3= 0.000 deg,
      \tJ4= 90.000 deg,\tJ5= -60.000 deg,\tJ6= 45.000 deg
      };
      /END
      """;

  record Outcome(PendantCommandTest.Run run, List<double[]> rows) {
    /** Highest speed (mm/s) of the point whose x column is {@code col}, over rows from..to. */
    double maxSpeed(int col, int from, int to) {
      double max = 0;
      for (int k = Math.max(1, from); k < Math.min(rows.size(), to); k++) {
        double[] a = rows.get(k - 1);
        double[] b = rows.get(k);
        double d = Math.sqrt(Math.pow(b[col] - a[col], 2) + Math.pow(b[col + 1] - a[col + 1], 2)
            + Math.pow(b[col + 2] - a[col + 2], 2));
        max = Math.max(max, d / (b[0] - a[0]));
      }
      return max;
    }

    double maxSpeed(int col) {
      return maxSpeed(col, 1, rows.size());
    }

    /** Index of the first row at or after {@code timeSec}. */
    int rowAt(double timeSec) {
      for (int k = 0; k < rows.size(); k++) {
        if (rows.get(k)[0] >= timeSec - 1e-9) {
          return k;
        }
      }
      return rows.size();
    }

    String out() {
      return run.out();
    }
  }

  private static Outcome pendant(Path dir, String keys, String... options) throws Exception {
    Path ls = dir.resolve("FAST.LS");
    Files.writeString(ls, PROGRAM);
    Path script = dir.resolve("s.keys");
    Files.writeString(script, keys);
    Path trace = dir.resolve("trace.csv");
    List<String> args = new java.util.ArrayList<>(List.of("pendant", "--program", ls.toString(), "--keys",
        script.toString(), "--trace", trace.toString()));
    args.addAll(List.of(options));
    PendantCommandTest.Run r = PendantCommandTest.run(args.toArray(String[]::new));
    assertThat(r.exitCode()).as(r.err()).isZero();
    List<double[]> rows = Files.readAllLines(trace).stream().skip(1)
        .map(l -> java.util.Arrays.stream(l.split(",")).mapToDouble(Double::parseDouble).toArray()).toList();
    return new Outcome(r, rows);
  }

  /** Select FAST, raise the override to 100% (SHIFT +% twice: 50, 100), cursor on line 1. */
  private static final String SELECT_AT_100 = """
      SELECT
      ENTER
      SHIFT++%
      SHIFT++%
      ITEM
      TYPE 1
      ENTER
      """;

  @Test
  void aT1ProgramNeverExceeds250MmPerSecAtTheTcpOrTheFlangeAndT2Does(@TempDir Path dir) throws Exception {
    String keys = "HOLD DEADMAN\n" + SELECT_AT_100 + """
        HOLD SHIFT
        FWD
        WAIT 25
        RELEASE SHIFT
        SHOW
        """;
    Outcome t1 = pendant(dir, keys);
    assertThat(t1.out()).contains("FAST         LINE 3    T1   ABORTED");
    double limit = 250 + ROUNDING_MM_PER_SEC;
    assertThat(t1.maxSpeed(TCP_X)).isLessThanOrEqualTo(limit).isGreaterThan(240);
    assertThat(t1.maxSpeed(FLANGE_X)).isLessThanOrEqualTo(limit).isGreaterThan(240);

    // the same program in T2 goes at the programmed speed: the cap is T1's
    Outcome t2 = pendant(dir, keys, "--mode", "T2");
    assertThat(t2.out()).contains("FAST         LINE 3    T2   ABORTED");
    assertThat(t2.maxSpeed(TCP_X)).isGreaterThan(1000);
  }

  @Test
  void aT1JointJogIsCappedAt250MmPerSec(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, """
        HOLD DEADMAN
        SHIFT++%
        SHIFT++%
        HOLD SHIFT
        HOLD +X/J1
        WAIT 1
        RELEASE +X/J1
        RELEASE SHIFT
        """);
    assertThat(o.rows().get(o.rows().size() - 1)[1]).as("J1 moved").isGreaterThan(5);
    assertThat(o.maxSpeed(TCP_X)).isLessThanOrEqualTo(250 + ROUNDING_MM_PER_SEC).isGreaterThan(240);
  }

  @Test
  void releasingShiftInT1PausesTheProgramDeceleratingAndShiftFwdResumes(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, "HOLD DEADMAN\n" + SELECT_AT_100 + """
        HOLD SHIFT
        FWD
        WAIT 1
        RELEASE SHIFT
        WAIT 1
        SHOW
        HOLD SHIFT
        FWD
        WAIT 25
        RELEASE SHIFT
        SHOW
        """);
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("T1   PAUSED").contains("hold-to-run").doesNotContain("SRVO");
    // paused, not alarmed: the arm decelerated (it still moved in the tick after the release) and stood still
    int release = o.rowAt(1.0);
    assertThat(o.maxSpeed(TCP_X, release + 1, release + 2)).isGreaterThan(1);
    assertThat(o.maxSpeed(TCP_X, o.rowAt(1.5), o.rowAt(2.0))).isZero();
    // SHIFT+FWD resumed it to the end
    assertThat(shows[2]).contains("LINE 3    T1   ABORTED");
  }

  @Test
  void releasingTheDeadmanInT1IsSrvo003AndStopsTheArmAtOnce(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, "HOLD DEADMAN\n" + SELECT_AT_100 + """
        HOLD SHIFT
        FWD
        WAIT 1
        RELEASE DEADMAN
        WAIT 1
        SHOW
        RELEASE SHIFT
        RESET
        SHOW
        HOLD DEADMAN
        RESET
        HOLD SHIFT
        FWD
        WAIT 25
        RELEASE SHIFT
        SHOW
        """);
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("SRVO-003 Deadman switch released").contains("T1   PAUSED");
    // stopped at once: no motion in the tick after the release
    int release = o.rowAt(1.0);
    assertThat(o.maxSpeed(TCP_X, release + 1, o.rowAt(2.0))).isZero();
    // RESET without the DEADMAN does not clear it for good: the pendant is still enabled and let go
    assertThat(shows[3]).doesNotContain("SRVO-003").contains("LINE 3    T1   ABORTED");
  }

  @Test
  void anEstopStopsTheArmWithinOneTickAndResetWorksOnlyAfterRelease(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, "HOLD DEADMAN\n" + SELECT_AT_100 + """
        HOLD SHIFT
        FWD
        WAIT 1
        ESTOP
        WAIT 0.5
        RESET
        SHOW
        RELEASE ESTOP
        RESET
        SHOW
        """);
    int pressed = o.rowAt(1.0);
    assertThat(o.maxSpeed(TCP_X, pressed - 10, pressed)).as("moving before").isGreaterThan(50);
    double[] at = o.rows().get(pressed);
    for (int k = pressed + 1; k < o.rows().size(); k++) {
      assertThat(o.rows().get(k)[TCP_X]).isCloseTo(at[TCP_X], within(1e-9));
      assertThat(o.rows().get(k)[1]).isCloseTo(at[1], within(1e-9));
    }
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("SRVO-002 (FAST, 2) Teach pendant E-stop").contains("E-STOP")
        .contains("E-stop still pressed");
    assertThat(shows[2]).doesNotContain("SRVO-002").contains("Alarm reset");
  }

  @Test
  void inAutoThePendantCannotJogAndCycleStartRunsWithTheTpOff(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, """
        MODE AUTO
        HOLD DEADMAN
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        SHOW
        RELEASE +X/J1
        RELEASE SHIFT
        """ + SELECT_AT_100 + """
        CYCLE START
        SHOW
        TP OFF
        CYCLE START
        WAIT 25
        SHOW
        """);
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("AUTO mode: the pendant cannot jog");
    assertThat(o.rows().get(o.rowAt(0.5))[1]).isZero();
    assertThat(shows[2]).contains("CYCLE START refused: the TP is enabled");
    assertThat(shows[3]).contains("LINE 3    AUTO ABORTED").contains("TP-OFF");
    // AUTO runs at the programmed speed
    assertThat(o.maxSpeed(TCP_X)).isGreaterThan(1000);
  }

  @Test
  void aScriptStartsAtTheColdStartOverrideOf10Percent(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, "SHOW\n+%\nSHOW\n");
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("T1   ABORTED JOINT  10%");
    assertThat(shows[2]).contains(" 15%");
  }

  @Test
  void vfineAndFineJogOneStepPerKeyPressOfTheDocumentedSize(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, """
        -% *4
        SHOW
        COORD *2
        HOLD DEADMAN
        HOLD SHIFT
        +X
        +X
        +X
        WAIT 0.1
        HOLD +X
        WAIT 1
        RELEASE +X
        WAIT 0.1
        +%
        SHOW
        -X
        WAIT 0.1
        RELEASE SHIFT
        COORD *3
        HOLD SHIFT
        J1+
        WAIT 0.1
        """);
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("VFINE");
    assertThat(shows[2]).contains(" FINE");
    double[] first = o.rows().get(0);
    // VFINE: four presses (one held for a second) = four steps of 0.002 mm along WORLD X
    double[] afterVfine = o.rows().get(o.rowAt(1.2));
    assertThat(afterVfine[TCP_X] - first[TCP_X]).isCloseTo(4 * 0.002, within(2e-4));
    assertThat(afterVfine[TCP_X + 1] - first[TCP_X + 1]).isCloseTo(0, within(2e-4));
    // FINE: one press back = 0.023 mm
    double[] afterFine = o.rows().get(o.rowAt(1.3));
    assertThat(afterVfine[TCP_X] - afterFine[TCP_X]).isCloseTo(0.023, within(2e-4));
    // FINE in JOINT: 0.001 deg of J1
    double[] last = o.rows().get(o.rows().size() - 1);
    assertThat(last[1] - first[1]).isCloseTo(0.001, within(1e-6));
  }

  @Test
  void jgfrmJogsAlongTheActiveJogFrameSetInSetupFrames(@TempDir Path dir) throws Exception {
    Outcome o = pendant(dir, """
        MENU
        5
        F1
        3
        F2
        DOWN *5
        TYPE 90
        ENTER
        SHOW
        PREV
        COORD
        HOLD DEADMAN
        HOLD SHIFT
        HOLD +X
        WAIT 0.5
        RELEASE +X
        WAIT 0.2
        RELEASE SHIFT
        SHOW
        """);
    String[] shows = o.out().split("-- SHOW");
    assertThat(shows[1]).contains("Jog Frame 1").contains("R {    90.000}");
    assertThat(shows[2]).contains("JGFRM");
    double[] first = o.rows().get(0);
    double[] last = o.rows().get(o.rows().size() - 1);
    // JOGFRAME[1] is WORLD turned 90 deg about Z: its +X is WORLD +Y
    double dy = last[TCP_X + 1] - first[TCP_X + 1];
    assertThat(dy).isGreaterThan(5);
    assertThat(Math.abs(last[TCP_X] - first[TCP_X])).isLessThan(0.01 * dy);
  }
}
