package org.robotrun.io.bench;

/**
 * Realistic .LS text of any length for parse benchmarks: the statements of a pick-and-place
 * program (motions with options, register arithmetic with parentheses, IF, WAIT with timeout,
 * I/O, remarks) repeated, with a valid /POS so the file checks clean.
 */
public final class LsBenchPrograms {
  private LsBenchPrograms() {}

  private static final String[] BODY = {
    "J P[1:HOME] 30% FINE    ;",
    "L P[2:PICK] 400mm/sec CNT50 Tool_Offset,PR[12:UP50]    ;",
    "  R[1:I]=R[1:I]+1    ;",
    "  PR[10,3:STACK]=(R[1:I]-1)*20    ;",
    "  IF R[1:I]>100,JMP LBL[1] ;",
    "  WAIT RI[1:CLOSED]=ON TIMEOUT,LBL[1] ;",
    "  RO[1:GRIP]=ON ;",
    "  WAIT    .20(sec) ;",
    "  ! place the part ;",
    "L P[3:PLACE] 400mm/sec FINE Offset,PR[10:STACK] ACC80    ;",
  };

  /** A program of exactly {@code lines} /MN lines (at least 1). */
  public static String program(int lines) {
    StringBuilder sb = new StringBuilder(lines * 48 + 1024);
    sb.append("/PROG  BENCH\n/ATTR\nCOMMENT\t\t= \"parse benchmark\";\n/MN\n");
    for (int i = 1; i < lines; i++) {
      lineNumber(sb, i).append(BODY[i % BODY.length]).append('\n');
    }
    lineNumber(sb, Math.max(1, lines)).append("  LBL[1] ;\n");
    sb.append("/POS\n");
    sb.append("P[1:\"HOME\"]{\n   GP1:\n\tUF : 1, UT : 1,\n"
        + "\tJ1=     0.000 deg,\tJ2=     0.000 deg,\tJ3=     0.000 deg,\n"
        + "\tJ4=     0.000 deg,\tJ5=   -90.000 deg,\tJ6=     0.000 deg\n};\n");
    for (int p = 2; p <= 3; p++) {
      sb.append("P[").append(p).append("]{\n   GP1:\n\tUF : 1, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n"
          + "\tX =   350.000  mm,\tY =  -120.000  mm,\tZ =    40.000  mm,\n"
          + "\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n");
    }
    sb.append("/END\n");
    return sb.toString();
  }

  private static StringBuilder lineNumber(StringBuilder sb, int n) {
    String s = Integer.toString(n);
    for (int i = s.length(); i < 4; i++) {
      sb.append(' ');
    }
    return sb.append(s).append(':');
  }
}
