package org.robotrun.program;

import java.util.Arrays;

/**
 * A program prepared for execution: one op per line, labels in a sorted table, block structure
 * (FOR/ENDFOR, IF…THEN/ELSE/ENDIF, SELECT groups) matched, and per line whether backward
 * execution may pass over it. Built once per program version by {@link Compiler}.
 */
final class CompiledProgram {
  final Program program;
  final String name;
  final Ops.Op[] ops;
  final boolean[] motion;
  /** Per line: "" when backward execution passes over it, else the statement name that stops it. */
  final String[] backwardBlocker;
  private final int[] labelNumbers;
  private final int[] labelLines;
  /** First structure error (line index and message), or -1 / null when the program is well formed. */
  final int structureErrorLine;
  final String structureError;

  CompiledProgram(Program program, Ops.Op[] ops, boolean[] motion, String[] backwardBlocker, int[] labelNumbers,
      int[] labelLines, int structureErrorLine, String structureError) {
    this.program = program;
    this.name = program.name();
    this.ops = ops;
    this.motion = motion;
    this.backwardBlocker = backwardBlocker;
    this.labelNumbers = labelNumbers;
    this.labelLines = labelLines;
    this.structureErrorLine = structureErrorLine;
    this.structureError = structureError;
  }

  /** Line index of LBL[n], or -1. */
  int labelLine(int n) {
    int k = Arrays.binarySearch(labelNumbers, n);
    return k >= 0 ? labelLines[k] : -1;
  }
}
