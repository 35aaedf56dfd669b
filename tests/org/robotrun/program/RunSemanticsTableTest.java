package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;

/**
 * The run side's value rules as tables, each row from the language's documents, never from a run:
 * docs/tp-execution.md ("Values", "Alarms"), docs/tp-language.md and docs/alarms.md (codes and
 * ranges). Every range is tried below, at and above its bounds; every expected value is computed
 * here from the rule (Java's own arithmetic where the rule is arithmetic).
 */
class RunSemanticsTableTest {

  static Program parse(String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  T\n/ATTR\nDEFAULT_GROUP\t= *,*,*,*,*;\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format(Locale.ROOT, "%4d:  %s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n/END\n");
    LsReadResult r = LsReader.parse("T.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics() + "\n" + sb).isFalse();
    return r.program();
  }

  /** Runs the lines to the end; fails on anything else. */
  static Rig run(String... lines) {
    Rig rig = new Rig(parse(lines));
    Outcome o = rig.run();
    assertThat(o).as(String.join("\n", lines)).isInstanceOf(Outcome.Finished.class);
    return rig;
  }

  /** Runs the lines and answers the alarm they raise. */
  static Alarm alarm(String... lines) {
    Rig rig = new Rig(parse(lines));
    Outcome o = rig.run();
    assertThat(o).as(String.join("\n", lines)).isInstanceOf(Outcome.Alarmed.class);
    return ((Outcome.Alarmed) o).alarm();
  }

  /** A row: lines that end normally, or the alarm code they raise on a given line. */
  record Row(String name, String alarmCode, int alarmLine, String... lines) {}

  static Row ok(String name, String... lines) {
    return new Row(name, null, 0, lines);
  }

  static Row fails(String name, String code, int line, String... lines) {
    return new Row(name, code, line, lines);
  }

  static Stream<DynamicTest> table(List<Row> rows) {
    return rows.stream().map(r -> DynamicTest.dynamicTest(r.name() + (r.alarmCode() == null ? " runs" : " alarms " + r.alarmCode()), () -> {
      if (r.alarmCode() == null) {
        run(r.lines());
      } else {
        Alarm a = alarm(r.lines());
        assertThat(a.code()).as(a.toString()).isEqualTo(r.alarmCode());
        assertThat(a.line()).as(a.toString()).isEqualTo(r.alarmLine());
      }
    }));
  }

  // ------------------------------------------------------------------ ranges of values

  @TestFactory
  Stream<DynamicTest> valueRangesBelowAtAndAboveTheirBounds() {
    List<Row> rows = new ArrayList<>();
    // OVERRIDE and $MCR.$GENOVERRIDE: 1..100 (docs/alarms.md INTP-304)
    for (String form : new String[] {"OVERRIDE=R[1]%", "$MCR.$GENOVERRIDE=R[1]"}) {
      rows.add(fails(form + " 0", "INTP-304", 2, "R[1]=0", form));
      rows.add(ok(form + " 1", "R[1]=1", form));
      rows.add(ok(form + " 100", "R[1]=100", form));
      rows.add(fails(form + " 101", "INTP-304", 2, "R[1]=101", form));
    }
    // $WAITTMOUT: 0..32767 hundredths of a second (docs/tp-language.md)
    rows.add(fails("$WAITTMOUT -1", "INTP-304", 2, "R[1]=(-1)", "$WAITTMOUT=R[1]"));
    rows.add(ok("$WAITTMOUT 0", "R[1]=0", "$WAITTMOUT=R[1]"));
    rows.add(ok("$WAITTMOUT 32767", "R[1]=32767", "$WAITTMOUT=R[1]"));
    rows.add(fails("$WAITTMOUT 32768", "INTP-304", 2, "R[1]=32768", "$WAITTMOUT=R[1]"));
    // frame numbers 0..10 (docs/alarms.md INTP-304: a frame number outside 0..10)
    for (String form : new String[] {"UFRAME_NUM=R[1]", "UTOOL_NUM=R[1]", "$MNUFRAMENUM[1]=R[1]", "$MNUTOOLNUM[1]=R[1]",
        "OFFSET CONDITION PR[1],UFRAME[R[1]]"}) {
      rows.add(fails(form + " -1", "INTP-304", 2, "R[1]=(-1)", form));
      rows.add(ok(form + " 0", "R[1]=0", form));
      rows.add(ok(form + " 10", "R[1]=10", form));
      rows.add(fails(form + " 11", "INTP-304", 2, "R[1]=11", form));
    }
    return table(rows);
  }

  @Test
  void frameNumbersAndOverridesReachThePort() {
    Rig rig = run("R[1]=7", "UFRAME_NUM=R[1]", "UTOOL_NUM=3", "OVERRIDE=35%", "R[2]=$MNUFRAMENUM[1]",
        "R[3]=$MNUTOOLNUM[1]", "R[4]=$MCR.$GENOVERRIDE", "$MCR.$GENOVERRIDE=60", "R[5]=$MCR.$GENOVERRIDE",
        "$MNUTOOLNUM[1]=4", "$MNUFRAMENUM[1]=5", "$WAITTMOUT=250", "R[6]=$WAITTMOUT", "R[7]=$JCR.$JOG_GP");
    assertThat(rig.regs.number(2)).isEqualTo(7);
    assertThat(rig.regs.number(3)).isEqualTo(3);
    assertThat(rig.regs.number(4)).isEqualTo(35);
    assertThat(rig.regs.number(5)).isEqualTo(60);
    assertThat(rig.port.overridePct()).isEqualTo(60);
    assertThat(rig.port.activeFrame(Instruction.FrameKind.TOOL)).isEqualTo(4);
    assertThat(rig.port.activeFrame(Instruction.FrameKind.USER)).isEqualTo(5);
    assertThat(rig.regs.number(6)).isEqualTo(250);
    assertThat(rig.regs.isInteger(6)).isTrue();
    assertThat(rig.regs.number(7)).isEqualTo(1);
  }

  // ------------------------------------------------------------------ tables and indexes

  @TestFactory
  Stream<DynamicTest> everyTableFromOneToItsSizeThroughAnIndirectIndex() {
    // docs/tp-execution.md: R[1..200], PR[1..100], F[1..200], TIMER[1..10], SR[1..25], and the
    // default I/O DI/DO[1..512], RI/RO[1..8], GI/GO[1..100], AI/AO[1..64]; outside: INTP-204.
    record T(String name, int size, String read, String write) {}
    List<T> tables = List.of(
        new T("R", 200, "R[9]=R[R[1]]", "R[R[1]]=1"),
        new T("PR", 100, "R[9]=PR[R[1],1]", "PR[R[1],1]=1"),
        new T("F", 200, "F[9]=F[R[1]]", "F[R[1]]=ON"),
        new T("TIMER", 10, "R[9]=TIMER[R[1]]", "TIMER[R[1]]=START"),
        new T("SR", 25, "SR[9]=SR[R[1]]", "SR[R[1]]='A'"),
        new T("DO", 512, "F[9]=DO[R[1]]", "DO[R[1]]=ON"),
        new T("DI", 512, "F[9]=DI[R[1]]", null),
        new T("RO", 8, "F[9]=RO[R[1]]", "RO[R[1]]=OFF"),
        new T("RI", 8, "F[9]=RI[R[1]]", null),
        new T("GO", 100, "R[9]=GO[R[1]]", "GO[R[1]]=5"),
        new T("GI", 100, "R[9]=GI[R[1]]", null),
        new T("AO", 64, "R[9]=AO[R[1]]", "AO[R[1]]=5"),
        new T("AI", 64, "R[9]=AI[R[1]]", null),
        new T("SO", 15, "F[9]=SO[R[1]]", null),
        new T("SI", 15, "F[9]=SI[R[1]]", null));
    List<Row> rows = new ArrayList<>();
    for (T t : tables) {
      for (String line : t.write() == null ? new String[] {t.read()} : new String[] {t.read(), t.write()}) {
        rows.add(fails(line + " with 0", "INTP-204", 2, "R[1]=0", line));
        rows.add(ok(line + " with 1", "R[1]=1", line));
        rows.add(ok(line + " with " + t.size(), "R[1]=" + t.size(), line));
        rows.add(fails(line + " with " + (t.size() + 1), "INTP-204", 2, "R[1]=" + (t.size() + 1), line));
      }
    }
    // a PR element is 1..6
    rows.add(fails("PR[1,0] read", "INTP-204", 2, "R[1]=0", "R[9]=PR[1,R[1]]"));
    rows.add(ok("PR[1,6] read", "R[1]=6", "R[9]=PR[1,R[1]]"));
    rows.add(fails("PR[1,7] read", "INTP-204", 2, "R[1]=7", "R[9]=PR[1,R[1]]"));
    rows.add(fails("PR[1,0] write", "INTP-204", 2, "R[1]=0", "PR[1,R[1]]=5"));
    rows.add(ok("PR[1,1] write", "R[1]=1", "PR[1,R[1]]=5"));
    rows.add(ok("PR[1,6] write", "R[1]=6", "PR[1,R[1]]=5"));
    rows.add(fails("PR[1,7] write", "INTP-204", 2, "R[1]=7", "PR[1,R[1]]=5"));
    // a direct index outside the table (the reader warns; the line alarms when it runs)
    rows.add(fails("R[201]=1", "INTP-204", 2, "R[1]=1", "R[201]=1"));
    rows.add(fails("R[9]=R[201]", "INTP-204", 2, "R[1]=1", "R[9]=R[201]"));
    rows.add(ok("R[200]=R[200]+1", "R[1]=1", "R[200]=R[200]+1"));
    // the index register itself is R[1..200], and must hold a whole number
    rows.add(fails("R[R[1]] with R[1]=2.5", "INTP-204", 2, "R[1]=2.5", "R[9]=R[R[1]]"));
    rows.add(ok("R[R[1]] with R[1]=2.0", "R[1]=2.0", "R[9]=R[R[1]]"));
    // frames: UFRAME[1..10]=PR[], PAYLOAD[1..10]
    rows.add(fails("UFRAME[0]=PR[1]", "INTP-204", 2, "R[1]=0", "UFRAME[R[1]]=PR[1]"));
    rows.add(ok("UFRAME[10]=PR[1]", "R[1]=10", "UFRAME[R[1]]=PR[1]"));
    rows.add(fails("UFRAME[11]=PR[1]", "INTP-204", 2, "R[1]=11", "UFRAME[R[1]]=PR[1]"));
    rows.add(fails("UTOOL[11]=PR[1]", "INTP-204", 2, "R[1]=11", "UTOOL[R[1]]=PR[1]"));
    rows.add(fails("PR[1]=UFRAME[11]", "INTP-204", 2, "R[1]=11", "PR[1]=UFRAME[R[1]]"));
    rows.add(ok("PR[1]=UTOOL[10]", "R[1]=10", "PR[1]=UTOOL[R[1]]"));
    rows.add(fails("PAYLOAD[0]", "INTP-204", 2, "R[1]=0", "PAYLOAD[R[1]]"));
    rows.add(ok("PAYLOAD[10]", "R[1]=10", "PAYLOAD[R[1]]"));
    rows.add(fails("PAYLOAD[11]", "INTP-204", 2, "R[1]=11", "PAYLOAD[R[1]]"));
    // position register arithmetic and copies, every index checked
    rows.add(fails("PR[101]=PR[1]", "INTP-204", 2, "R[1]=101", "PR[R[1]]=PR[1]"));
    rows.add(fails("PR[1]=PR[101]", "INTP-204", 2, "R[1]=101", "PR[1]=PR[R[1]]"));
    rows.add(fails("PR[1]=PR[101]+PR[1]", "INTP-204", 2, "R[1]=101", "PR[1]=PR[R[1]]+PR[2]"));
    rows.add(fails("PR[1]=PR[1]-PR[101]", "INTP-204", 2, "R[1]=101", "PR[1]=PR[2]-PR[R[1]]"));
    rows.add(ok("PR[100]=PR[1]+PR[100]", "R[1]=100", "PR[R[1]]=PR[1]+PR[R[1]]"));
    return table(rows);
  }

  // ------------------------------------------------------------------ I/O kinds

  @TestFactory
  Stream<DynamicTest> ioKindsInputsOutputsGroupsAndPulses() {
    List<Row> rows = new ArrayList<>();
    rows.add(fails("GO=2.5", "INTP-205", 2, "R[1]=2.5", "GO[1]=R[1]"));
    rows.add(ok("GO=2.0", "R[1]=2.0", "GO[1]=R[1]"));
    rows.add(fails("GO=ON", "INTP-205", 1, "GO[1]=(ON)"));
    rows.add(fails("DO='A'", "INTP-205", 2, "SR[1]='A'", "DO[1]=SR[1]"));
    return table(rows);
  }

  @Test
  void inputsCannotBeSetAndOnlyDigitalOutputsPulse() {
    // The reader and the pendant refuse these lines; a program model holding one still alarms when
    // it runs: SIMU-004 for an input (docs/alarms.md), INTP-205 for a pulse on a group output.
    for (IoKind in : new IoKind[] {IoKind.DI, IoKind.RI, IoKind.GI, IoKind.SI, IoKind.AI}) {
      for (Instruction line : new Instruction[] {Tp.setIo(in, 1, in.group() ? Tp.num(3) : Tp.on()), Tp.pulse(in, 1, 0.5)}) {
        Rig rig = new Rig(Tp.prog("T", Tp.setR(1, Tp.num(1)), line));
        Alarm a = rig.alarm(rig.run());
        assertThat(a.code()).as(line.toString()).isEqualTo("SIMU-004");
        assertThat(a.line()).isEqualTo(2);
      }
    }
    for (IoKind out : new IoKind[] {IoKind.GO, IoKind.AO}) {
      Rig rig = new Rig(Tp.prog("T", Tp.pulse(out, 1, 0.5)));
      assertThat(rig.alarm(rig.run()).code()).as(out.name()).isEqualTo("INTP-205");
    }
    for (IoKind out : new IoKind[] {IoKind.DO, IoKind.RO, IoKind.F}) {
      Rig rig = new Rig(Tp.prog("T", Tp.setIo(out, 2, Tp.num(3))));
      assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
      assertThat(rig.regs.bit(out, 2)).isTrue();
    }
  }

  @Test
  void aDigitalOutputTakenFromARegisterIsOnForAnyNonZeroValue() {
    // docs/tp-execution.md: DO[i]=R[j] is ON for any non-zero value.
    double[] values = {0, 1, -1, 0.5, 2, -0.25};
    for (double v : values) {
      String set = v == Math.rint(v) ? "R[1]=" + (v < 0 ? "(" + (long) v + ")" : Long.toString((long) v))
          : "R[1]=" + (v < 0 ? "(" + v + ")" : Double.toString(v));
      Rig rig = run("DO[3]=ON", "RO[2]=ON", "F[4]=ON", set, "DO[3]=R[1]", "RO[2]=R[1]", "F[4]=(R[1]<>0)");
      assertThat(rig.regs.bit(IoKind.DO, 3)).as("DO for %s", v).isEqualTo(v != 0);
      assertThat(rig.regs.bit(IoKind.RO, 2)).as("RO for %s", v).isEqualTo(v != 0);
      assertThat(rig.regs.bit(IoKind.F, 4)).as("F for %s", v).isEqualTo(v != 0);
    }
    Rig rig = run("GO[2]=R[1]", "R[1]=37", "GO[3]=R[1]", "AO[4]=(-12)", "R[2]=GO[3]", "R[3]=AO[4]");
    assertThat(rig.regs.value(IoKind.GO, 2)).isZero();
    assertThat(rig.regs.value(IoKind.GO, 3)).isEqualTo(37);
    assertThat(rig.regs.number(2)).isEqualTo(37);
    assertThat(rig.regs.isInteger(2)).isTrue();
    assertThat(rig.regs.number(3)).isEqualTo(-12);
  }

  @Test
  void aPulseWithoutAWidthLastsTheDefaultPulseWidth() {
    // $DEFPULSE: 0.4 s by default (docs/tp-execution.md); the program does not wait for it.
    Rig rig = new Rig(parse("DO[5]=PULSE", "RO[1]=PULSE,0.2sec", "R[1]=1"));
    rig.interp.forward();
    rig.tick(0.0);
    assertThat(rig.regs.number(1)).as("the program went on at once").isEqualTo(1);
    assertThat(rig.regs.bit(IoKind.DO, 5)).isTrue();
    assertThat(rig.regs.bit(IoKind.RO, 1)).isTrue();
    rig.tick(0.19);
    assertThat(rig.regs.bit(IoKind.RO, 1)).isTrue();
    rig.tick(0.02);
    assertThat(rig.regs.bit(IoKind.RO, 1)).isFalse();
    assertThat(rig.regs.bit(IoKind.DO, 5)).isTrue();
    rig.tick(0.18); // 0.39 s
    assertThat(rig.regs.bit(IoKind.DO, 5)).isTrue();
    rig.tick(0.02); // 0.41 s
    assertThat(rig.regs.bit(IoKind.DO, 5)).isFalse();
  }

  // ------------------------------------------------------------------ arithmetic

  @Test
  void integerArithmeticStaysIntegerWhileItFitsThirtyTwoBits() {
    // docs/tp-execution.md: + - * of integers give an integer (a real if the result leaves 32 bits)
    long[][] cases = {
        {Integer.MAX_VALUE, 0}, {Integer.MAX_VALUE - 1, 1}, {Integer.MAX_VALUE, 1},
        {Integer.MIN_VALUE + 1, -1}, {Integer.MIN_VALUE, -1}, {-5, 3}};
    for (long[] c : cases) {
      long a = c[0];
      long b = c[1];
      Rig rig = new Rig(parse("R[3]=R[1]+R[2]", "R[4]=R[1]-(-1)*R[2]", "R[5]=R[1]*1", "R[6]=R[2]-R[1]"));
      rig.regs.setInteger(1, (int) a);
      rig.regs.setInteger(2, (int) b);
      assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
      long sum = a + b;
      boolean fits = sum >= Integer.MIN_VALUE && sum <= Integer.MAX_VALUE;
      assertThat(rig.regs.number(3)).as("%d+%d", a, b).isEqualTo((double) sum);
      assertThat(rig.regs.isInteger(3)).as("%d+%d integer", a, b).isEqualTo(fits);
      assertThat(rig.regs.number(4)).isEqualTo((double) sum);
      assertThat(rig.regs.isInteger(4)).isEqualTo(fits);
      assertThat(rig.regs.isInteger(5)).isTrue();
      long diff = b - a;
      assertThat(rig.regs.number(6)).isEqualTo((double) diff);
      assertThat(rig.regs.isInteger(6)).isEqualTo(diff >= Integer.MIN_VALUE && diff <= Integer.MAX_VALUE);
    }
  }

  @Test
  void divisionByZeroInEveryDivisionAlarmsOnItsLine() {
    for (String op : new String[] {"/", "DIV", "MOD"}) {
      for (String zero : new String[] {"0", "0.0"}) {
        Alarm a = alarm("R[1]=7", "R[2]=" + zero, "R[3]=R[1]" + (op.equals("/") ? "/" : " " + op + " ") + "R[2]", "R[4]=1");
        assertThat(a.code()).as(op).isEqualTo("SIMU-001");
        assertThat(a.kind()).isEqualTo(AlarmKind.DIVIDE_BY_ZERO);
        assertThat(a.line()).isEqualTo(3);
        assertThat(a.message()).contains("'" + op + "'");
      }
    }
  }

  @Test
  void divAndModOfRealsAndMixedOperands() {
    // DIV truncates toward zero (an integer); MOD takes the sign of the dividend, x - (x DIV y)*y.
    double[][] cases = {{7.5, 2}, {-7.5, 2}, {7.5, -2}, {9, 3}, {1, 4}, {-1, 4}};
    for (double[] c : cases) {
      Rig rig = new Rig(parse("R[3]=R[1] DIV R[2]", "R[4]=R[1] MOD R[2]", "R[5]=R[1]/R[2]"));
      rig.regs.setReal(1, c[0]);
      rig.regs.setInteger(2, (int) c[1]);
      assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
      double q = c[0] / c[1];
      double div = q < 0 ? Math.ceil(q) : Math.floor(q);
      assertThat(rig.regs.number(3)).as("%s DIV %s", c[0], c[1]).isEqualTo(div);
      assertThat(rig.regs.isInteger(3)).isTrue();
      assertThat(rig.regs.number(4)).as("%s MOD %s", c[0], c[1]).isCloseTo(c[0] - div * c[1], within(1e-12));
      assertThat(rig.regs.isInteger(4)).as("a real dividend gives a real remainder").isFalse();
      assertThat(rig.regs.number(5)).isEqualTo(q);
      assertThat(rig.regs.isInteger(5)).isFalse();
    }
    Rig ints = run("R[1]=(-9) MOD 4", "R[2]=9 MOD (-4)", "R[3]=(-9) DIV 4");
    assertThat(ints.regs.number(1)).isEqualTo(-1);
    assertThat(ints.regs.isInteger(1)).isTrue();
    assertThat(ints.regs.number(2)).isEqualTo(1);
    assertThat(ints.regs.number(3)).isEqualTo(-2);
  }

  @Test
  void overflowBeyondWhatARegisterHoldsIsAnAlarm() {
    // docs/alarms.md INTP-304: arithmetic overflowed what a register holds.
    Rig rig = new Rig(parse("R[2]=R[1]*R[1]", "R[3]=1"));
    rig.regs.setReal(1, 1e200);
    Alarm a = rig.alarm(rig.run());
    assertThat(a.code()).isEqualTo("INTP-304");
    assertThat(a.line()).isEqualTo(1);
    for (String line : new String[] {"R[2]=R[1]+R[1]", "R[2]=(-R[1])-R[1]", "R[2]=R[1]/0.0000001", "R[2]=EXP[R[4]]"}) {
      Rig r = new Rig(parse(line));
      r.regs.setReal(1, 1.7e308);
      r.regs.setReal(4, 1000);
      assertThat(r.alarm(r.run()).code()).as(line).isEqualTo("INTP-304");
    }
  }

  @TestFactory
  Stream<DynamicTest> typeMismatchesAreIntp205() {
    // docs/alarms.md INTP-205: arithmetic on ON/OFF, AND/OR on numbers, a string where a number goes...
    List<Row> rows = new ArrayList<>();
    for (String line : new String[] {"R[1]=ON+1", "R[1]=1-ON", "R[1]=(ON*2)", "R[1]=(ON/2)", "R[1]=(ON DIV 2)",
        "R[1]=(2 MOD ON)", "R[1]=(-ON)", "F[1]=(!R[2])", "F[1]=(R[2] AND ON)", "F[1]=(ON OR R[2])",
        "F[1]=(ON<1)", "F[1]=(ON=1)", "F[1]=('A'<'B')", "R[1]=ABS[ON]", "R[1]=SQRT['A']",
        "R[1]=('A'-1)", "R[1]=('A'*1)", "F[1]=(ON>OFF)", "F[1]=('A'=1)"}) {
      rows.add(fails(line, "INTP-205", 1, line));
    }
    rows.add(fails("R[]=string without a number", "INTP-205", 2, "SR[1]='ABC'", "R[1]=SR[1]"));
    rows.add(fails("IF on a number", "INTP-205", 1, "IF R[1],JMP LBL[1]", "LBL[1]"));
    rows.add(fails("WAIT on a number", "INTP-205", 1, "WAIT R[1]+1", "R[2]=1"));
    rows.add(fails("FOR bound real", "INTP-205", 2, "R[2]=1.5", "FOR R[1]=1 TO R[2]", "ENDFOR"));
    rows.add(fails("FOR start real", "INTP-205", 2, "R[2]=0.5", "FOR R[1]=R[2] TO 3", "ENDFOR"));
    rows.add(fails("FOR counter made real", "INTP-205", 3, "FOR R[1]=1 TO 3", "R[1]=1.5", "ENDFOR"));
    rows.add(fails("SELECT value ON", "INTP-205", 2, "R[1]=3", "SELECT R[1]=ON,JMP LBL[1]", "LBL[1]"));
    rows.add(fails("PR[i,j]=ON", "INTP-205", 1, "PR[1,1]=(ON)"));
    rows.add(fails("SR[]=ON", "INTP-205", 1, "SR[1]=(ON)"));
    rows.add(fails("joint PR + Cartesian PR", "INTP-205", 3, "PR[1]=JPOS", "PR[2]=LPOS", "PR[3]=PR[1]+PR[2]"));
    rows.add(fails("LPOS - JPOS", "INTP-205", 1, "PR[3]=LPOS-JPOS"));
    rows.add(fails("UFRAME[1]=joint PR", "INTP-205", 2, "PR[1]=JPOS", "UFRAME[1]=PR[1]"));
    rows.add(ok("ON=ON and strings equal", "F[1]=(ON=ON)", "F[2]=(OFF<>ON)", "SR[1]='A'", "F[3]=(SR[1]='A')",
        "F[4]=(SR[1]<>'A')"));
    return table(rows);
  }

  @Test
  void comparisonsOfOnOffAndStringsFollowEquality() {
    Rig rig = run("F[1]=(ON=ON)", "F[2]=(ON=OFF)", "F[3]=(ON<>OFF)", "F[4]=(OFF<>OFF)", "SR[1]='PART'",
        "F[5]=(SR[1]='PART')", "F[6]=(SR[1]='PARTS')", "F[7]=(SR[1]<>'PART')", "F[8]=(SR[1]<>'X')");
    boolean[] expected = {true, false, true, false, true, false, false, true};
    for (int i = 0; i < expected.length; i++) {
      assertThat(rig.regs.bit(IoKind.F, i + 1)).as("F[%d]", i + 1).isEqualTo(expected[i]);
    }
  }

  @Test
  void andOrAndNotOverTheirFullTruthTables() {
    for (boolean a : new boolean[] {false, true}) {
      for (boolean b : new boolean[] {false, true}) {
        Rig rig = run("F[1]=" + (a ? "ON" : "OFF"), "F[2]=" + (b ? "ON" : "OFF"), "F[3]=(F[1] AND F[2])",
            "F[4]=(F[1] OR F[2])", "F[5]=(!F[1])", "F[6]=(!F[1] AND !F[2])", "R[1]=(F[1] OR F[2])");
        assertThat(rig.regs.bit(IoKind.F, 3)).as("%s AND %s", a, b).isEqualTo(a && b);
        assertThat(rig.regs.bit(IoKind.F, 4)).as("%s OR %s", a, b).isEqualTo(a || b);
        assertThat(rig.regs.bit(IoKind.F, 5)).isEqualTo(!a);
        assertThat(rig.regs.bit(IoKind.F, 6)).isEqualTo(!a && !b);
        // ON/OFF stored in R[] is 1/0, an integer
        assertThat(rig.regs.number(1)).isEqualTo(a || b ? 1 : 0);
        assertThat(rig.regs.isInteger(1)).isTrue();
      }
    }
  }

  // ------------------------------------------------------------------ strings

  @Test
  void stringRegistersJoinTextAndNumbersAsDocumented() {
    // docs/tp-execution.md: an integer as its digits, a real with up to six decimals and at least one.
    Rig rig = run("SR[1]='AB'", "SR[2]=SR[1]+7", "SR[3]=7+SR[1]", "SR[4]=SR[1]+2.5", "SR[5]=3.0", "SR[6]=(-12)",
        "SR[7]=1/3", "SR[8]=SR[1]+SR[1]", "SR[9]=(-2.5)", "SR[10]=2/3");
    assertThat(rig.regs.string(2)).isEqualTo("AB7");
    assertThat(rig.regs.string(3)).isEqualTo("7AB");
    assertThat(rig.regs.string(4)).isEqualTo("AB2.5");
    assertThat(rig.regs.string(5)).isEqualTo("3.0");
    assertThat(rig.regs.string(6)).isEqualTo("-12");
    assertThat(rig.regs.string(7)).isEqualTo("0.333333");
    assertThat(rig.regs.string(8)).isEqualTo("ABAB");
    assertThat(rig.regs.string(9)).isEqualTo("-2.5");
    assertThat(rig.regs.string(10)).isEqualTo("0.666667");
  }

  @Test
  void aStringRegisterHoldsAtMost254Characters() {
    String a127 = "A".repeat(127);
    Rig rig = run("SR[1]='" + a127 + "'", "SR[2]=SR[1]+SR[1]", "R[1]=STRLEN SR[2]");
    assertThat(rig.regs.string(2)).hasSize(254);
    assertThat(rig.regs.number(1)).isEqualTo(254);
    Alarm a = alarm("SR[1]='" + a127 + "'", "SR[2]=SR[1]+SR[1]+'B'");
    assertThat(a.code()).isEqualTo("INTP-304");
    assertThat(a.line()).isEqualTo(2);
  }

  @Test
  void substrFindstrAndStrlenAtTheEdgesOfTheString() {
    // SUBSTR x,m,n: the n characters from the m-th (1-based); a range outside the string alarms.
    String s = "ABCDE";
    for (int m = 0; m <= 6; m++) {
      for (int n = 0; n <= 6; n++) {
        boolean inside = m >= 1 && n >= 1 && m - 1 + n <= s.length();
        String[] lines = {"SR[1]='" + s + "'", "R[1]=" + m, "R[2]=" + n, "SR[2]=SUBSTR SR[1],R[1],R[2]"};
        if (inside) {
          assertThat(run(lines).regs.string(2)).as("SUBSTR %d,%d", m, n).isEqualTo(s.substring(m - 1, m - 1 + n));
        } else {
          Alarm a = alarm(lines);
          assertThat(a.code()).as("SUBSTR %d,%d", m, n).isEqualTo("INTP-304");
          assertThat(a.line()).isEqualTo(4);
        }
      }
    }
    // FINDSTR x,y: 1-based, case-insensitive, 0 when absent
    Rig rig = run("SR[1]='PickPart'", "R[1]=FINDSTR SR[1],'PICK'", "R[2]=FINDSTR SR[1],'part'", "R[3]=FINDSTR SR[1],'X'",
        "R[4]=STRLEN SR[1]", "R[5]=STRLEN SR[9]", "R[6]=FINDSTR SR[1],'t'");
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.regs.number(2)).isEqualTo(5);
    assertThat(rig.regs.number(3)).isEqualTo(0);
    assertThat(rig.regs.number(4)).isEqualTo(8);
    assertThat(rig.regs.number(5)).isEqualTo(0);
    assertThat(rig.regs.number(6)).isEqualTo(8);
    assertThat(rig.regs.isInteger(2)).isTrue();
    assertThat(rig.regs.isInteger(4)).isTrue();
  }

  @Test
  void aStringGivesTheNumberItStartsWith() {
    // docs/tp-execution.md: R[i]=SR[j] takes the number the string starts with ('12.5AB' gives the
    // real 12.5, '7' the integer 7); a string that does not start with a number alarms.
    record C(String text, double value, boolean integer) {}
    List<C> good = List.of(new C("12.5AB", 12.5, false), new C("7", 7, true), new C(" 42 ", 42, true),
        new C("-3X", -3, true), new C("+4", 4, true), new C("7.", 7, false), new C("-0.5", -0.5, false),
        new C("10E2", 10, true), new C(".5", 0.5, false));
    for (C c : good) {
      Rig rig = run("SR[1]='" + c.text() + "'", "R[1]=SR[1]");
      assertThat(rig.regs.number(1)).as("'%s'", c.text()).isEqualTo(c.value());
      assertThat(rig.regs.isInteger(1)).as("'%s' integer", c.text()).isEqualTo(c.integer());
    }
    for (String bad : new String[] {"", "ABC", ".", "-.", "+.", "-", "+X", " .E"}) {
      Alarm a = alarm("SR[1]='" + bad + "'", "R[1]=SR[1]");
      assertThat(a.code()).as("'%s'", bad).isEqualTo("INTP-205");
    }
  }

  // ------------------------------------------------------------------ functions

  @Test
  void truncAndRoundGiveIntegersRoundingHalfAwayFromZero() {
    double[] xs = {2.5, -2.5, 2.4, -2.4, 2.6, -2.6, 0.5, -0.5, 0, 7, -7, 2147483647.0, -2147483647.0};
    for (double x : xs) {
      Rig rig = new Rig(parse("R[2]=TRUNC[R[1]]", "R[3]=ROUND[R[1]]"));
      rig.regs.setReal(1, x);
      assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
      double trunc = x < 0 ? -Math.floor(-x) : Math.floor(x);
      double round = x < 0 ? -Math.floor(-x + 0.5) : Math.floor(x + 0.5);
      assertThat(rig.regs.number(2)).as("TRUNC %s", x).isEqualTo(trunc + 0.0);
      assertThat(rig.regs.number(3)).as("ROUND %s", x).isEqualTo(round + 0.0);
      assertThat(rig.regs.isInteger(2)).isTrue();
      assertThat(rig.regs.isInteger(3)).isTrue();
    }
    for (double x : new double[] {3e9, -3e9, 2147483648.0}) {
      for (String fn : new String[] {"TRUNC", "ROUND"}) {
        Rig rig = new Rig(parse("R[2]=" + fn + "[R[1]]"));
        rig.regs.setReal(1, x);
        assertThat(rig.alarm(rig.run()).code()).as("%s %s", fn, x).isEqualTo("INTP-304");
      }
    }
  }

  @Test
  void functionDomainsAtTheirEdges() {
    record F(String call, double arg, double expected) {}
    List<F> inside = List.of(new F("SQRT", 0, 0), new F("SQRT", 2.25, 1.5), new F("ASIN", 1, 90), new F("ASIN", -1, -90),
        new F("ACOS", -1, 180), new F("ACOS", 1, 0), new F("LN", 1, 0), new F("ABS", -2.5, 2.5), new F("ATAN", 1, 45),
        new F("SIN", 30, 0.5), new F("COS", 60, 0.5), new F("TAN", 45, 1), new F("EXP", 0, 1));
    for (F f : inside) {
      Rig rig = new Rig(parse("R[2]=" + f.call() + "[R[1]]"));
      rig.regs.setReal(1, f.arg());
      assertThat(rig.run()).as(f.toString()).isInstanceOf(Outcome.Finished.class);
      assertThat(rig.regs.number(2)).as(f.toString()).isCloseTo(f.expected(), within(1e-12));
      assertThat(rig.regs.isInteger(2)).as(f.toString()).isFalse();
    }
    List<F> outside = List.of(new F("SQRT", -1e-9, 0), new F("ASIN", 1.000001, 0), new F("ASIN", -1.000001, 0),
        new F("ACOS", 1.000001, 0), new F("ACOS", -1.000001, 0), new F("LN", 0, 0), new F("LN", -1, 0));
    for (F f : outside) {
      Rig rig = new Rig(parse("R[2]=" + f.call() + "[R[1]]"));
      rig.regs.setReal(1, f.arg());
      Alarm a = rig.alarm(rig.run());
      assertThat(a.code()).as(f.toString()).isEqualTo("INTP-304");
      assertThat(a.message()).contains(f.call());
    }
    Rig abs = run("R[1]=ABS[(-7)]", "R[2]=ABS[(-7.0)]");
    assertThat(abs.regs.number(1)).isEqualTo(7);
    assertThat(abs.regs.isInteger(1)).isTrue();
    assertThat(abs.regs.isInteger(2)).isFalse();
  }

  // ------------------------------------------------------------------ flow

  @Test
  void selectComparesTheRegisterByValueWhetherIntegerOrReal() {
    for (String value : new String[] {"2", "2.0", "3", "2.5"}) {
      Rig rig = run("R[1]=" + value, "SELECT R[1]=1,JMP LBL[1]", "       =2,JMP LBL[2]", "       =2.5,JMP LBL[3]",
          "       ELSE,JMP LBL[4]", "LBL[1]", "R[2]=1", "END", "LBL[2]", "R[2]=2", "END", "LBL[3]", "R[2]=3", "END",
          "LBL[4]", "R[2]=4");
      double v = Double.parseDouble(value);
      int expected = v == 1 ? 1 : v == 2 ? 2 : v == 2.5 ? 3 : 4;
      assertThat(rig.regs.number(2)).as("SELECT with R[1]=%s", value).isEqualTo(expected);
    }
  }

  @Test
  void aSelectCaseReachedByAJumpSkipsTheRestOfTheGroup() {
    Rig rig = run("JMP LBL[9]", "SELECT R[1]=1,JMP LBL[1]", "LBL[9]", "R[2]=5", "LBL[1]");
    assertThat(rig.regs.number(2)).isEqualTo(5);
    // a case line reached straight from the line above skips the group's remaining lines
    Rig rig2 = run("R[1]=7", "SELECT R[1]=1,JMP LBL[1]", "       =2,JMP LBL[1]", "       ELSE,JMP LBL[2]", "R[2]=1",
        "LBL[1]", "R[3]=1", "LBL[2]", "R[4]=1");
    assertThat(rig2.regs.number(2)).isZero();
    assertThat(rig2.regs.number(3)).isZero();
    assertThat(rig2.regs.number(4)).isEqualTo(1);
  }

  @Test
  void forLoopsAtTheirBoundsAgainstAJavaLoop() {
    int[][] bounds = {{1, 1}, {1, 3}, {3, 1}, {0, 0}, {-2, 2}, {5, 4}, {2, 2}};
    for (int[] b : bounds) {
      for (boolean down : new boolean[] {false, true}) {
        Rig rig = new Rig(parse("R[3]=0", "R[4]=0", "FOR R[1]=R[5] " + (down ? "DOWNTO" : "TO") + " R[6]",
            "R[3]=R[3]+1", "R[4]=R[4]*10+R[1]", "ENDFOR", "R[7]=R[1]"));
        rig.regs.setInteger(5, b[0]);
        rig.regs.setInteger(6, b[1]);
        assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
        int count = 0;
        long digits = 0;
        int last = b[0];
        for (int i = b[0]; down ? i >= b[1] : i <= b[1]; i += down ? -1 : 1) {
          count++;
          digits = digits * 10 + i;
          last = i;
        }
        String what = b[0] + (down ? " DOWNTO " : " TO ") + b[1];
        assertThat(rig.regs.number(3)).as(what + " count").isEqualTo(count);
        assertThat(rig.regs.number(4)).as(what + " values").isEqualTo((double) digits);
        // after a completed loop the counter holds the end value; a skipped loop leaves the start
        assertThat(rig.regs.number(7)).as(what + " counter after").isEqualTo(count == 0 ? b[0] : last);
        assertThat(rig.regs.isInteger(1)).isTrue();
      }
    }
  }

  @Test
  void forBoundsAtTheThirtyTwoBitLimitsAndWholeRealBounds() {
    // FOR bounds are whole numbers (INTP-205 otherwise); a real register holding a whole number serves.
    for (long bound : new long[] {Integer.MAX_VALUE, Integer.MIN_VALUE}) {
      Rig rig = new Rig(parse("FOR R[1]=R[5] TO R[5]", "R[3]=R[3]+1", "ENDFOR"));
      rig.regs.setInteger(5, (int) bound);
      assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
      assertThat(rig.regs.number(3)).as("FOR %d TO %d", bound, bound).isEqualTo(1);
      assertThat(rig.regs.number(1)).isEqualTo((double) bound);
    }
    Rig rig = new Rig(parse("FOR R[1]=R[5] TO R[6]", "R[3]=R[3]+1", "ENDFOR"));
    rig.regs.setReal(5, 1.0);
    rig.regs.setReal(6, 3.0);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(3)).isEqualTo(3);
    assertThat(rig.regs.isInteger(1)).as("the counter is an integer").isTrue();
  }

  @Test
  void anIndirectJumpReachesALabelOnTheFirstLine() {
    // JMP LBL[R[i]] is resolved when it runs (docs/tp-language.md); LBL[1] on line 1 is a label like any other.
    Rig rig = run("LBL[1]", "R[2]=R[2]+1", "R[1]=1", "IF R[2]<3,JMP LBL[R[1]]", "R[1]=7", "JMP LBL[R[1]]", "R[3]=1", "LBL[7]");
    assertThat(rig.regs.number(2)).isEqualTo(3);
    assertThat(rig.regs.number(3)).isZero();
    Alarm a = alarm("R[1]=8", "JMP LBL[R[1]]", "LBL[7]");
    assertThat(a.code()).isEqualTo("INTP-224");
    assertThat(a.line()).isEqualTo(2);
  }

  @Test
  void aSelectOnTheLastLineOfTheProgram() {
    for (int v = 1; v <= 2; v++) {
      Rig rig = run("R[1]=" + v, "JMP LBL[5]", "LBL[1]", "R[2]=1", "END", "LBL[5]", "SELECT R[1]=1,JMP LBL[1]");
      assertThat(rig.regs.number(2)).isEqualTo(v == 1 ? 1 : 0);
    }
  }

  @Test
  void anEndforWithoutItsRunningForIsAStructureAlarm() {
    // jumping into a loop body reaches ENDFOR while its FOR is not running
    Alarm a = alarm("JMP LBL[1]", "FOR R[1]=1 TO 3", "LBL[1]", "ENDFOR");
    assertThat(a.code()).isEqualTo("SIMU-002");
    assertThat(a.line()).isEqualTo(4);
    assertThat(a.message()).contains("line 2");
  }

  @Test
  void timersStartStopAndResetInSimulatedTime() {
    Rig rig = new Rig(parse("TIMER[3]=START", "WAIT 0.50(sec)", "TIMER[3]=STOP", "R[1]=TIMER[3]", "WAIT 0.30(sec)",
        "R[2]=TIMER[3]", "TIMER[3]=RESET", "R[3]=TIMER[3]"));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isCloseTo(0.5, within(0.0041));
    assertThat(rig.regs.isInteger(1)).isFalse();
    assertThat(rig.regs.number(2)).isEqualTo(rig.regs.number(1));
    assertThat(rig.regs.number(3)).isZero();
  }

  @Test
  void userAlarmAbortAndPauseAsTheTableSays() {
    Alarm u = alarm("R[1]=1", "UALM[3]");
    assertThat(u.code()).isEqualTo("INTP-213");
    assertThat(u.line()).isEqualTo(2);
    assertThat(u.message()).isEqualTo("UALM[3]");
    Alarm ab = alarm("ABORT", "R[1]=1");
    assertThat(ab.code()).isEqualTo("SIMU-005");
    Rig rig = new Rig(parse("R[1]=1", "PAUSE", "R[1]=2"));
    assertThat(rig.run()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
    rig.interp.forward();
    assertThat(rig.runUntilStopped(0.004, 100)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(2);
  }
}
