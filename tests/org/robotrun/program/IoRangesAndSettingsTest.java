package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The I/O sizes a controller is configured with (docs/tp-execution.md, "Values": by default
 * DI/DO[1..512], RI/RO[1..8], GI/GO[1..100], F[1..200], SI/SO[1..15], AI/AO[1..64]; UOP UI[1..18],
 * UO[1..20], which a scenario cannot resize; a scenario may set others up to 4096), the system
 * variables a program reads ($MIX_BG[n].$STATUS from the task port) and the interpreter's settings
 * (docs/tp-execution.md: 100 000 lines a tick, CALL 32 deep, $WAITTMOUT 30 s, $DEFPULSE 0.4 s).
 */
class IoRangesAndSettingsTest {

  @Test
  void theDefaultSizesAreTheDocumentedOnes() {
    Map<IoKind, Integer> documented = Map.ofEntries(Map.entry(IoKind.DI, 512), Map.entry(IoKind.DO, 512),
        Map.entry(IoKind.RI, 8), Map.entry(IoKind.RO, 8), Map.entry(IoKind.GI, 100), Map.entry(IoKind.GO, 100),
        Map.entry(IoKind.F, 200), Map.entry(IoKind.SI, 15), Map.entry(IoKind.SO, 15), Map.entry(IoKind.AI, 64),
        Map.entry(IoKind.AO, 64), Map.entry(IoKind.UI, 18), Map.entry(IoKind.UO, 20));
    for (IoKind k : IoKind.values()) {
      assertThat(IoRanges.DEFAULT.size(k)).as(k.name()).isEqualTo(documented.get(k));
      assertThat(new Registers().ioSize(k)).as(k.name()).isEqualTo(documented.get(k));
    }
    assertThat(IoRanges.of(Map.of())).isEqualTo(IoRanges.DEFAULT);
    assertThat(IoRanges.of(Map.of()).hashCode()).isEqualTo(IoRanges.DEFAULT.hashCode());
    assertThat(IoRanges.DEFAULT.toString()).startsWith("IoRanges[DI=512, DO=512,").endsWith("UO=20]");
  }

  @Test
  void aScenarioResizesAKindFromOneTo4096ButNotTheUopSignals() {
    IoRanges r = IoRanges.of(Map.of("DO", 1024, "RI", 1, "AI", 4096));
    assertThat(r.size(IoKind.DO)).isEqualTo(1024);
    assertThat(r.size(IoKind.RI)).isEqualTo(1);
    assertThat(r.size(IoKind.AI)).isEqualTo(4096);
    assertThat(r.size(IoKind.DI)).isEqualTo(512);
    assertThat(r).isNotEqualTo(IoRanges.DEFAULT);
    assertThatThrownBy(() -> IoRanges.of(Map.of("DO", 0))).isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("1..4096");
    assertThatThrownBy(() -> IoRanges.of(Map.of("DO", 4097))).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> IoRanges.of(Map.of("UI", 20))).isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("UOP");
    assertThatThrownBy(() -> IoRanges.of(Map.of("UO", 20))).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> IoRanges.of(Map.of("XO", 2))).isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("unknown I/O kind 'XO'").hasMessageContaining("DI, DO");
    assertThat(IoRanges.kind("GO")).isEqualTo(IoKind.GO);

    // a program on a cell with DO[1..1024] reaches DO[1024], and DO[1025] alarms (INTP-204)
    Program p = RunSemanticsTableTest.parse("DO[R[1]]=ON");
    Rig ok = new Rig(InterpreterSettings.defaults().withIoRanges(r), 0.1, p);
    ok.regs.setInteger(1, 1024);
    assertThat(ok.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(ok.regs.bit(IoKind.DO, 1024)).isTrue();
    Rig bad = new Rig(InterpreterSettings.defaults().withIoRanges(r), 0.1, p);
    bad.regs.setInteger(1, 1025);
    assertThat(bad.alarm(bad.run()).code()).isEqualTo("INTP-204");
  }

  @Test
  void backgroundLogicSlotStatusComesFromTheTaskPort() {
    assertThat(SystemVariables.backgroundSlot("$MIX_BG[3].$STATUS")).isEqualTo(3);
    assertThat(SystemVariables.backgroundSlot("$MIX_BG[100].$STATUS")).isEqualTo(100);
    assertThat(SystemVariables.backgroundSlot("$MIX_BG[1000].$STATUS")).isZero();
    assertThat(SystemVariables.backgroundSlot("$MIX_BG[].$STATUS")).isZero();
    assertThat(SystemVariables.backgroundSlot("$MIX_BG[A].$STATUS")).isZero();
    assertThat(SystemVariables.backgroundSlot("$MIX_BG[3].$STATE")).isZero();
    assertThat(SystemVariables.backgroundSlot("$MIX_BX[3].$STATUS")).isZero();
    assertThat(SystemVariables.supported("$waittmout")).contains("$WAITTMOUT");
    assertThat(SystemVariables.supported("$mix_bg[2].$status")).contains("$MIX_BG[2].$STATUS");
    assertThat(SystemVariables.supported("$SCR.$ITP_SPEED")).isEmpty();
    assertThat(SystemVariables.writable("$mcr.$genoverride")).contains("$MCR.$GENOVERRIDE");
    assertThat(SystemVariables.writable("$JCR.$JOG_GP")).isEmpty();

    Rig rig = new Rig(RunSemanticsTableTest.parse("R[1]=$MIX_BG[1].$STATUS", "R[2]=$MIX_BG[2].$STATUS",
        "R[3]=$MIX_BG[3].$STATUS"));
    rig.interp.setTaskPort(new TaskPort() {
      @Override
      public Optional<String> run(String program) {
        return Optional.empty();
      }

      @Override
      public int backgroundStatus(int slot) {
        return slot == 1 ? 2 : slot == 2 ? 1 : 0;
      }
    });
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(2);
    assertThat(rig.regs.number(2)).isEqualTo(1);
    assertThat(rig.regs.number(3)).isZero();
    assertThat(rig.regs.isInteger(1)).isTrue();
  }

  @Test
  void settingsDefaultsAndTheirChecks() {
    InterpreterSettings d = InterpreterSettings.defaults();
    assertThat(d.instructionBudgetPerTick()).isEqualTo(100_000);
    assertThat(d.maxCallDepth()).isEqualTo(32);
    assertThat(d.waitTimeoutSec()).isEqualTo(30.0);
    assertThat(d.defaultPulseSec()).isEqualTo(0.4);
    assertThat(d.ioRanges()).isEqualTo(IoRanges.DEFAULT);
    assertThat(d.macros()).isEmpty();
    assertThatThrownBy(() -> d.withBudget(0)).isInstanceOf(IllegalArgumentException.class);
    assertThat(d.withBudget(1).instructionBudgetPerTick()).isEqualTo(1);
    assertThatThrownBy(() -> new InterpreterSettings(1, 0, 30, 0.4, Map.of())).isInstanceOf(IllegalArgumentException.class);
    assertThat(new InterpreterSettings(1, 1, 30, 0.4, Map.of()).maxCallDepth()).isEqualTo(1);
    InterpreterSettings s = d.withMacros(Map.of("  open   hand 1 ", "HOPEN")).withWaitTimeoutSec(5).withUserAlarmMessages(
        Map.of(2, "DOOR OPEN"));
    assertThat(s.macros()).containsEntry("OPEN HAND 1", "HOPEN");
    assertThat(s.waitTimeoutSec()).isEqualTo(5);
    assertThat(s.userAlarmMessages()).containsEntry(2, "DOOR OPEN");
    assertThat(s.withBudget(7).macros()).containsEntry("OPEN HAND 1", "HOPEN");
    assertThat(s.withIoRanges(IoRanges.DEFAULT).waitTimeoutSec()).isEqualTo(5);
    assertThat(InterpreterSettings.macroKey(" Close\thand  2 ")).isEqualTo("CLOSE HAND 2");

    // a budget of one line a tick: the second line is a runaway (SIMU-003), a wait resets the count
    Rig rig = new Rig(d.withBudget(2), 0.1, RunSemanticsTableTest.parse("R[1]=1", "R[2]=1", "R[3]=1"));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.code()).isEqualTo("SIMU-003");
    assertThat(a.line()).isEqualTo(3);
    Rig ok = new Rig(d.withBudget(2), 0.1, RunSemanticsTableTest.parse("R[1]=1", "R[2]=1"));
    assertThat(ok.run()).isInstanceOf(Outcome.Finished.class);
    // the wait timeout of the settings is $WAITTMOUT at start
    Rig w = new Rig(d.withWaitTimeoutSec(5), 0.1, RunSemanticsTableTest.parse("R[1]=$WAITTMOUT"));
    assertThat(w.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(w.regs.number(1)).isEqualTo(500);
  }
}
