package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A STOP-severity motion fault in a called program, through a key script on the real controller
 * (docs/alarms.md "Severity"): the program pauses in the callee with its call stack; RESET, a
 * TOUCHUP that removes the fault, then SHIFT+FWD (TP ON, DEADMAN and SHIFT held) re-runs the line
 * and returns to the caller, which runs to its end.
 */
class PendantAlarmSeverityTest {
  private static final String MAIN = """
      /PROG  MAIN
      /ATTR
      /MN
         1:CALL SUB ;
         2:R[1]=R[1]+1 ;
         3:MESSAGE[BACK IN MAIN] ;
      /POS
      /END
      """;

  /** P[2] needs J5 = -140 deg, outside the default robot's J5 limits: MOTN-017 on line 2. */
  private static final String SUB = """
      /PROG  SUB
      /ATTR
      /MN
         1:J P[1] 100% FINE ;
         2:J P[2] 100% FINE ;
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
      \tJ1= 0.000 deg,\tJ2= 0.000 deg,\tJ3= 0.000 deg,
      \tJ4= 0.000 deg,\tJ5= -140.000 deg,\tJ6= 0.000 deg
      };
      /END
      """;

  @Test
  void aJointLimitInACalledProgramPausesThereAndResumesIntoTheCallerAfterTouchup(@TempDir Path dir)
      throws Exception {
    Path main = dir.resolve("MAIN.LS");
    Path sub = dir.resolve("SUB.LS");
    Files.writeString(main, MAIN);
    Files.writeString(sub, SUB);
    Path script = dir.resolve("s.keys");
    Files.writeString(script, """
        HOLD DEADMAN
        SELECT
        ENTER
        HOLD SHIFT
        FWD
        WAIT 10
        RELEASE SHIFT
        SHOW
        RESET
        SHOW
        HOLD SHIFT
        FWD
        WAIT 2
        RELEASE SHIFT
        SHOW
        RESET
        SHIFT+F5
        HOLD SHIFT
        FWD
        WAIT 10
        RELEASE SHIFT
        SHOW
        """);
    PendantCommandTest.Run r = PendantCommandTest.run("pendant", "--program", main.toString(), "--program",
        sub.toString(), "--keys", script.toString());
    assertThat(r.exitCode()).as(r.err()).isZero();
    String[] shows = r.out().split("-- SHOW");
    // the alarm pauses SUB on its line 2 (not ABORTED: the call stack is kept)
    assertThat(shows[1]).contains("SUB          LINE 2    T1   PAUSED").contains("MOTN-017 (SUB, 2)");
    // RESET clears it; still paused in SUB, the edit screen on the faulty line
    assertThat(shows[2]).contains("SUB          LINE 2    T1   PAUSED").doesNotContain("MOTN-017")
        .contains("EDIT SUB");
    // SHIFT+FWD without a fix runs the same line into the same alarm
    assertThat(shows[3]).contains("SUB          LINE 2    T1   PAUSED").contains("MOTN-017 (SUB, 2)");
    // after TOUCHUP of P[2] where the arm stands, the line runs, SUB returns and MAIN ends
    assertThat(shows[4]).contains("MAIN         LINE 3    T1   ABORTED").doesNotContain("MOTN-017");
    assertThat(r.out()).contains("BACK IN MAIN");
  }
}
