package org.robotrun.program.bench;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The benchmark workload does what it claims (so its figure counts real lines). */
class InterpreterWorkloadTest {

  @Test
  void runExecutesTheCountedLinesAndComputesTheSum() {
    InterpreterWorkload w = new InterpreterWorkload(14);
    assertThat(w.run()).isEqualTo(w.linesPerRun());
    // R[3] sums (i MOD 7)*3 for the i whose value is at most 10: i MOD 7 in 0..3, twice over 1..14.
    assertThat(w.checksum()).isEqualTo(2 * (0 + 3 + 6 + 9));
    // A second run starts afresh.
    assertThat(w.run()).isEqualTo(w.linesPerRun());
    assertThat(w.checksum()).isEqualTo(36);
  }

  @Test
  void jmhOperationCountMatchesTheWorkload() {
    assertThat(new InterpreterWorkload(InterpreterBenchmark.LOOPS).linesPerRun()).isEqualTo(InterpreterBenchmark.LINES);
  }
}
