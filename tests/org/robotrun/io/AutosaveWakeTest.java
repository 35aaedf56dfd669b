package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;

/**
 * Issue 29 (idle under 1 % of a core): the idle window sleeps until the autosave owes a look at
 * the content, and a finished write wakes it to show "saved".
 */
class AutosaveWakeTest {
  private static Scenario cell() {
    return ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/empty-cell.json"))).scenario();
  }

  @Test
  void aPollIsOwedOnlyAfterAChangeAndThenOneIntervalAfterTheLastLook(@TempDir Path tmp) throws Exception {
    try (Workspace ws = Workspace.open(tmp.resolve("ws"), cell())) {
      WorkspaceSnapshot snap = new WorkspaceSnapshot(
          ScenarioWriter.toJson(ws.scenario(), java.util.Optional.of(SavedState.fresh("")), ws.folder()), Map.of());
      List<String> reports = new ArrayList<>();
      CountDownLatch written = new CountDownLatch(1);
      try (Autosave a = new Autosave(ws, () -> snap, reports::add)) {
        a.setAfterWrite(written::countDown);
        long t0 = 1_000_000_000_000L;
        // never looked: owed at once
        assertThat(a.nextPollNanos(t0)).isEqualTo(t0);
        a.poll(t0);
        // a change after the look (a frame drawn for input at t0 + 0.1 s): owed one interval after the look
        assertThat(a.nextPollNanos(t0 + 100_000_000L)).isEqualTo(t0 + Autosave.CHECK_INTERVAL_NANOS);
        // no change since the look: nothing owed, the window may sleep
        assertThat(a.nextPollNanos(t0 - 1)).isEqualTo(Long.MAX_VALUE);
        a.poll(t0 + Autosave.CHECK_INTERVAL_NANOS);
        assertThat(a.nextPollNanos(t0 + 100_000_000L)).isEqualTo(Long.MAX_VALUE);
        // the first look handed the content to the writer, which wakes the window when done
        assertThat(written.await(10, TimeUnit.SECONDS)).isTrue();
        assertThat(a.status()).startsWith("saved ");
      }
    }
  }
}
