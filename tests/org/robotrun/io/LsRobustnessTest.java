package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Bad input of every kind gives diagnostics; nothing escapes as an exception. */
class LsRobustnessTest {

  private static final Path PICK3 = Path.of("tests/resources/programs/PICK3.LS");

  private static List<String> messages(LsReadResult r) {
    return r.diagnostics().stream().map(Diagnostic::toString).toList();
  }

  /** A syntactically clean program of {@code lines} /MN lines cycling through common statements. */
  static String bigProgram(int lines) {
    StringBuilder sb = new StringBuilder(lines * 40);
    sb.append("/PROG  BIG\n/ATTR\n/MN\n");
    String[] body = {
      "J P[1:HOME] 30% FINE    ;", "L P[2] 400mm/sec CNT50 Tool_Offset,PR[12:UP50]    ;",
      "  R[1:I]=R[1:I]+1    ;", "  PR[10,3:STACK]=(R[1:I]-1)*20    ;", "  IF R[1]>100,JMP LBL[1] ;",
      "  WAIT DI[1]=ON TIMEOUT,LBL[1] ;", "  RO[1:GRIP]=ON ;", "  WAIT    .20(sec) ;", "  ! a remark ;"};
    for (int i = 1; i <= lines - 1; i++) {
      String n = Integer.toString(i);
      sb.append(" ".repeat(Math.max(0, 4 - n.length()))).append(n).append(':').append(body[i % body.length]).append('\n');
    }
    String n = Integer.toString(lines);
    sb.append(" ".repeat(Math.max(0, 4 - n.length()))).append(n).append(":  LBL[1] ;\n");
    sb.append("/POS\n");
    sb.append("P[1:\"HOME\"]{\n   GP1:\n\tUF : 1, UT : 1,\n\tJ1=     0.000 deg,\tJ2=     0.000 deg,\tJ3=     0.000 deg,\n"
        + "\tJ4=     0.000 deg,\tJ5=   -90.000 deg,\tJ6=     0.000 deg\n};\n");
    sb.append("P[2]{\n   GP1:\n\tUF : 1, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n\tX =   350.000  mm,\tY =  -120.000  mm,"
        + "\tZ =    40.000  mm,\n\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n/END\n");
    return sb.toString();
  }

  @Test
  void emptyFile() {
    assertThat(messages(LsReader.parse("e.ls", ""))).containsExactly(
        "e.ls:1: empty file: expected an ASCII .LS program starting with '/PROG  NAME'");
    assertThat(LsReader.parse("e.ls", " \n\t\n").hasErrors()).isTrue();
  }

  @Test
  void binaryGarbage() {
    Random rnd = new Random(42);
    for (int round = 0; round < 50; round++) {
      byte[] bytes = new byte[1 + rnd.nextInt(4000)];
      rnd.nextBytes(bytes);
      LsReadResult r = LsReader.parse("g.bin", LsReader.decode(bytes));
      assertThat(r.hasErrors()).isTrue();
      assertThat(r.diagnostics()).hasSizeLessThanOrEqualTo(3);
    }
  }

  @Test
  void everyTruncationOfPick3IsReportedNotThrown() throws IOException {
    String text = Files.readString(PICK3, StandardCharsets.UTF_8);
    for (int cut = 0; cut < text.length() - 1; cut++) {
      LsReadResult r = LsReader.parse("cut.ls", text.substring(0, cut));
      assertThat(r.hasErrors()).as("cut at %d", cut).isTrue();
    }
  }

  @Test
  void randomDamageToGoldenProgramsNeverThrows() throws IOException {
    Random rnd = new Random(7);
    String chars = "[](){}:;,=<>+-*/%!'\"\t .0123456789ABCPRJLxyz\n";
    for (String name : List.of("PICK3.LS", "STATEMENTS.LS", "MOTIONS.LS", "EXPRS.LS")) {
      String text = Files.readString(PICK3.resolveSibling(name), StandardCharsets.UTF_8);
      for (int round = 0; round < 100; round++) {
        StringBuilder sb = new StringBuilder(text);
        for (int k = 0; k < 1 + rnd.nextInt(5); k++) {
          int at = rnd.nextInt(sb.length());
          switch (rnd.nextInt(3)) {
            case 0 -> sb.deleteCharAt(at);
            case 1 -> sb.insert(at, chars.charAt(rnd.nextInt(chars.length())));
            default -> sb.setCharAt(at, chars.charAt(rnd.nextInt(chars.length())));
          }
        }
        LsReadResult r = LsReader.parse(name, sb.toString());
        // Whatever was read, even from a damaged file, writes and reads back as the same program.
        String written = LsWriter.write(r.program());
        LsReadResult again = LsReader.parse(name, written);
        assertThat(again.program()).as("round %d of %s:%n%s", round, name, sb).isEqualTo(r.program());
        assertThat(LsWriter.write(again.program())).isEqualTo(written);
      }
    }
  }

  @Test
  void hundredThousandLineProgram() {
    LsReadResult r = LsReader.parse("big.ls", bigProgram(100_000));
    assertThat(r.diagnostics()).isEmpty();
    assertThat(r.program().lineCount()).isEqualTo(100_000);
    assertThat(LsWriter.write(r.program())).startsWith("/PROG  BIG\n").contains("\n100000:  LBL[1] ;\n");
  }

  @Test
  void unterminatedPositionBlock() {
    LsReadResult r = LsReader.parse("u.ls", "/PROG  U\n/MN\n   1:J P[1] 10% FINE    ;\n/POS\nP[1]{\n   GP1:\n"
        + "\tUF : 1, UT : 1,\n\tJ1= 0.000 deg,\tJ2= 0.000 deg,\tJ3= 0.000 deg,\n");
    assertThat(messages(r)).containsExactly(
        "u.ls:3: warning: P[1] is used but /POS has no P[1]: the position is uninitialised and the line alarms when it runs",
        "u.ls:5: P[1] is not closed: expected '};' before the end of the /POS section",
        "u.ls:8: file ends without /END (truncated?)");
  }

  @Test
  void tenThousandNestedParentheses() {
    String deep = "(".repeat(10_000) + "1" + ")".repeat(10_000);
    LsReadResult r = LsReader.parse("d.ls", "/PROG  D\n/MN\n   1:  R[1]=" + deep + "    ;\n   2:  R[2]=!" + "-".repeat(10_000)
        + "R[1]    ;\n   3:  R[3]=1" + "+1".repeat(10_000) + "    ;\n/POS\n/END\n");
    assertThat(messages(r)).containsExactly(
        "d.ls:3: expression nested too deeply: at most 64 levels of parentheses and signs",
        "d.ls:4: expression nested too deeply: at most 64 levels of parentheses and signs",
        "d.ls:5: expression too long: more than 1000 operators in one statement");
    String ok = "(".repeat(64) + "1" + ")".repeat(64);
    assertThat(LsReader.parse("d.ls", "/PROG  D\n/MN\n   1:  R[1]=" + ok + "    ;\n/POS\n/END\n").diagnostics()).isEmpty();
  }

  @Test
  void aUtf8ByteOrderMarkBeforeProgIsIgnored(@org.junit.jupiter.api.io.TempDir Path dir) throws IOException {
    Path f = dir.resolve("BOM.LS");
    byte[] text = "/PROG  BOM\n/MN\n   1:  R[1]=1    ;\n/POS\n/END\n".getBytes(StandardCharsets.US_ASCII);
    byte[] all = new byte[text.length + 3];
    all[0] = (byte) 0xEF;
    all[1] = (byte) 0xBB;
    all[2] = (byte) 0xBF;
    System.arraycopy(text, 0, all, 3, text.length);
    Files.write(f, all);
    LsReadResult r = LsReader.read(f);
    assertThat(messages(r)).isEmpty();
    assertThat(r.program().name()).isEqualTo("BOM");
  }

  @Test
  void aFileThatIsNotUtf8IsReadAsLatin1WithAWarning(@org.junit.jupiter.api.io.TempDir Path dir) throws IOException {
    Path f = dir.resolve("L1.LS");
    byte[] head = "/PROG  L1\n/MN\n   1:  ! caf".getBytes(StandardCharsets.US_ASCII);
    byte[] tail = " ;\n/POS\n/END\n".getBytes(StandardCharsets.US_ASCII);
    byte[] all = new byte[head.length + 1 + tail.length];
    System.arraycopy(head, 0, all, 0, head.length);
    all[head.length] = (byte) 0xE9; // 'é' in Latin-1, not valid UTF-8 on its own
    System.arraycopy(tail, 0, all, head.length + 1, tail.length);
    Files.write(f, all);
    LsReadResult r = LsReader.read(f);
    assertThat(messages(r)).containsExactly(
        f + ":3: warning: not UTF-8: read as Latin-1 (ISO-8859-1), as controllers write it; written back in Latin-1");
    assertThat(r.program().line(1)).isEqualTo(new org.robotrun.program.Instruction.Comment(" caf\u00e9"));
    // Written back as read: the Latin-1 byte is not turned into UTF-8.
    assertThat(LsWriter.bytes(r.program())).isEqualTo(all);
  }

  @Test
  void aMegabyteLineGivesAShortMessage() {
    String huge = "X".repeat(1_000_000);
    LsReadResult r = LsReader.parse("h.ls", "/PROG  H\n/MN\n   1:  R[1:" + huge + "]=" + huge + " ;\n/POS\n/END\n");
    assertThat(messages(r)).containsExactly(
        "h.ls:3: expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found '"
            + "X".repeat(40) + "...'");
  }

  @Test
  void unreadableFilesAreIoExceptionsNotDiagnostics() {
    org.assertj.core.api.Assertions.assertThatThrownBy(() -> LsReader.read(Path.of("tests/resources/programs/NOPE.LS")))
        .isInstanceOf(IOException.class);
    org.assertj.core.api.Assertions.assertThatThrownBy(() -> LsReader.read(Path.of("tests/resources/programs")))
        .isInstanceOf(IOException.class);
  }

  /**
   * The bound: a 10 000-line program parses in at most 200 ms. Measured once, after
   * three warm-up parses, as CPU time of this thread, so other processes on a busy machine do
   * not count (a steady-state parse takes about 20 ms; see {@code robotrun bench parse}).
   */
  @Test
  void tenThousandLinesParseWithinTwoHundredMilliseconds() {
    String text = bigProgram(10_000);
    for (int i = 0; i < 3; i++) {
      LsReader.parse("warm.ls", text);
    }
    java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
    boolean cpu = threads.isCurrentThreadCpuTimeSupported();
    long t0 = cpu ? threads.getCurrentThreadCpuTime() : System.nanoTime();
    LsReadResult r = LsReader.parse("big.ls", text);
    long ms = ((cpu ? threads.getCurrentThreadCpuTime() : System.nanoTime()) - t0) / 1_000_000;
    assertThat(r.diagnostics()).isEmpty();
    assertThat(ms).as("parse time of 10 000 lines in ms").isLessThanOrEqualTo(200);
  }
}
