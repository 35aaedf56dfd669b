package org.robotrun.program;

import java.util.Arrays;
import java.util.List;

/**
 * How the lines of one version of a program land in an edited version, so a paused program (or a
 * caller waiting for a CALL to return) goes on in the edited code at the corresponding line.
 *
 * <p>Lines are matched as a longest common subsequence of equal instructions: a line the edit did
 * not touch keeps its identity however many lines were inserted or deleted above it; a changed
 * line counts as deleted and replaced. Common leading and trailing lines are matched directly,
 * so a local edit of a long program costs little; if the differing middle is still huge (over
 * {@link #MAX_TABLE_CELLS} table cells) it is treated as wholly replaced rather than spending
 * seconds on the match.
 */
final class LineMap {
  /** Largest LCS table for the differing middle of two versions (ints; 16 MB). */
  static final int MAX_TABLE_CELLS = 4_000_000;

  /** Per line index of the old version: its index in the new version, or -1 (changed or deleted). */
  private final int[] newIndex;

  private LineMap(int[] newIndex) {
    this.newIndex = newIndex;
  }

  /** Matches the lines of {@code before} with those of {@code after}. */
  static LineMap between(List<Instruction> before, List<Instruction> after) {
    int n = before.size();
    int m = after.size();
    int[] map = new int[n];
    Arrays.fill(map, -1);
    int head = 0;
    while (head < n && head < m && before.get(head).equals(after.get(head))) {
      map[head] = head;
      head++;
    }
    int tail = 0;
    while (tail < n - head && tail < m - head && before.get(n - 1 - tail).equals(after.get(m - 1 - tail))) {
      map[n - 1 - tail] = m - 1 - tail;
      tail++;
    }
    int a = n - head - tail;
    int b = m - head - tail;
    if (a > 0 && b > 0 && (long) (a + 1) * (b + 1) <= MAX_TABLE_CELLS) {
      // lcs[i][j]: length of the LCS of before[head+i..] and after[head+j..] (middle only)
      int w = b + 1;
      int[] lcs = new int[(a + 1) * w];
      for (int i = a - 1; i >= 0; i--) {
        for (int j = b - 1; j >= 0; j--) {
          lcs[i * w + j] = before.get(head + i).equals(after.get(head + j))
              ? lcs[(i + 1) * w + j + 1] + 1
              : Math.max(lcs[(i + 1) * w + j], lcs[i * w + j + 1]);
        }
      }
      int i = 0;
      int j = 0;
      while (i < a && j < b) {
        if (before.get(head + i).equals(after.get(head + j))) {
          map[head + i] = head + j;
          i++;
          j++;
        } else if (lcs[(i + 1) * w + j] >= lcs[i * w + j + 1]) {
          i++;
        } else {
          j++;
        }
      }
    }
    return new LineMap(map);
  }

  /** The new index of old line {@code oldIndex} when the edit left it as it was, else -1. */
  int kept(int oldIndex) {
    return oldIndex >= 0 && oldIndex < newIndex.length ? newIndex[oldIndex] : -1;
  }

  /**
   * Where old position {@code oldIndex} (a line index, or the old line count for "past the end")
   * stands in the new version: the line's new index when it was kept, else the line that took
   * its place, i.e. the one right after the nearest kept line above (the new line count when
   * nothing follows).
   */
  int position(int oldIndex) {
    int k = kept(oldIndex);
    if (k >= 0) {
      return k;
    }
    for (int i = Math.min(oldIndex, newIndex.length) - 1; i >= 0; i--) {
      if (newIndex[i] >= 0) {
        return newIndex[i] + 1;
      }
    }
    return 0;
  }

  /**
   * Where a caller resumes after a CALL: {@code oldPc} is its next line, the line above it the
   * one that made the call. The call line kept: just below it in the new version (so lines
   * inserted right after the CALL run); changed or deleted: the position of {@code oldPc}.
   */
  int returnPoint(int oldPc) {
    int call = kept(oldPc - 1);
    return call >= 0 ? call + 1 : position(oldPc);
  }
}
