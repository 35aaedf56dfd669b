package org.robotrun.io;

import java.io.IOException;
import java.time.LocalTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Saves a workspace without the user asking: {@link #poll} runs on the thread that owns the
 * simulation (every frame of the window, every script step of {@code pendant --workspace}) and
 * does no I/O; at most every {@link #CHECK_INTERVAL_NANOS} it captures the workspace's content
 * (a string and program references) and, when that differs from what was last handed over,
 * passes it to a writer thread, which writes the changed files through {@link AtomicFiles}. A
 * change is therefore on disk within the check interval plus one write, well under 2 s.
 *
 * <p>A failed write (full disk, folder gone, no permission) is reported once through the
 * {@code report} callback and retried at every check until it succeeds; nothing already on
 * disk is harmed by a failure.
 */
public final class Autosave implements AutoCloseable {
  /** How often the content is compared with what was saved (0.5 s). */
  public static final long CHECK_INTERVAL_NANOS = 500_000_000L;

  private final Workspace workspace;
  private final Supplier<WorkspaceSnapshot> capture;
  private final Consumer<String> report;
  private final ExecutorService writer;
  private final AtomicReference<WorkspaceSnapshot> pending = new AtomicReference<>();
  private WorkspaceSnapshot handedOver;
  private long lastCheck = Long.MIN_VALUE;
  private volatile String problem = "";
  private volatile String status = "";
  private volatile Runnable afterWrite = () -> {};

  /**
   * @param capture the content now; called on the polling thread only
   * @param report receives each new problem and each recovery ("saved again"), on the writer thread
   */
  public Autosave(Workspace workspace, Supplier<WorkspaceSnapshot> capture, Consumer<String> report) {
    this.workspace = Objects.requireNonNull(workspace);
    this.capture = Objects.requireNonNull(capture);
    this.report = Objects.requireNonNull(report);
    this.writer = Executors.newSingleThreadExecutor(r -> {
      Thread t = new Thread(r, "robotrun-autosave");
      t.setDaemon(true);  // close() waits for the last write; a crash loses at most the interval
      return t;
    });
  }

  /** Call often (each frame); captures and hands over at most every 0.5 s. Never blocks on I/O. */
  public void poll(long nowNanos) {
    if (workspace.readOnly()) {
      return;
    }
    if (lastCheck != Long.MIN_VALUE && nowNanos - lastCheck < CHECK_INTERVAL_NANOS) {
      return;
    }
    lastCheck = nowNanos;
    submitIfChanged(capture.get(), false);
  }

  /**
   * When a window that sleeps while idle must wake to poll again ({@link System#nanoTime}), or
   * {@link Long#MAX_VALUE} when no poll is owed: one is owed once the content may have changed
   * ({@code changedSinceNanos}: the last frame drawn for input or motion) after the last check.
   */
  public long nextPollNanos(long changedSinceNanos) {
    if (workspace.readOnly() || lastCheck != Long.MIN_VALUE && lastCheck > changedSinceNanos) {
      return Long.MAX_VALUE;
    }
    return lastCheck == Long.MIN_VALUE ? changedSinceNanos : lastCheck + CHECK_INTERVAL_NANOS;
  }

  /** Runs on the writer thread after each write and each problem (a sleeping window wakes to show the new state). */
  public void setAfterWrite(Runnable r) {
    afterWrite = Objects.requireNonNull(r);
  }

  /** Saves now (Ctrl+S, Quit) and waits up to {@code timeoutMs} for the files to be on disk; returns the problem or "". */
  public String saveNow(long timeoutMs) {
    if (workspace.readOnly()) {
      return workspace.readOnlyReason();
    }
    Future<?> f = submitIfChanged(capture.get(), true);
    try {
      f.get(timeoutMs, TimeUnit.MILLISECONDS);
    } catch (java.util.concurrent.TimeoutException e) {
      return "saving is taking longer than " + timeoutMs / 1000.0 + " s (a slow or network disk?)";
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } catch (java.util.concurrent.ExecutionException e) {
      return String.valueOf(e.getCause().getMessage());
    }
    return problem;
  }

  private Future<?> submitIfChanged(WorkspaceSnapshot snap, boolean force) {
    boolean changed = handedOver == null || !snap.cellJson().equals(handedOver.cellJson())
        || !sameReferences(snap, handedOver);
    if (!changed && !force && problem.isEmpty()) {
      return java.util.concurrent.CompletableFuture.completedFuture(null);
    }
    handedOver = snap;
    pending.set(snap);
    return writer.submit(this::writePending);
  }

  private static boolean sameReferences(WorkspaceSnapshot a, WorkspaceSnapshot b) {
    if (a.otherScenarios().isPresent() != b.otherScenarios().isPresent()) {
      return false;
    }
    if (a.otherScenarios().isPresent()) {
      var x = a.otherScenarios().get();
      var y = b.otherScenarios().get();
      if (x.size() != y.size()) {
        return false;
      }
      for (int i = 0; i < x.size(); i++) {
        if (x.get(i) != y.get(i)) {
          return false;
        }
      }
    }
    if (a.programs().size() != b.programs().size()) {
      return false;
    }
    for (var e : a.programs().entrySet()) {
      if (b.programs().get(e.getKey()) != e.getValue()) {
        return false;
      }
    }
    return true;
  }

  /** On the writer thread: writes the newest content handed over (older ones are skipped). */
  private void writePending() {
    WorkspaceSnapshot snap = pending.getAndSet(null);
    if (snap == null) {
      return;
    }
    try {
      writeNow(snap);
    } finally {
      afterWrite.run();
    }
  }

  private void writeNow(WorkspaceSnapshot snap) {
    try {
      List<java.nio.file.Path> touched = workspace.save(snap);
      if (!problem.isEmpty()) {
        problem = "";
        report.accept("saved again: " + workspace.folder());
      }
      if (!touched.isEmpty()) {
        status = "saved " + LocalTime.now().format(DateTimeFormatter.ofPattern("HH:mm:ss"));
      }
    } catch (IOException e) {
      String message = e.getMessage() + " — your work is kept in the window; it is saved as soon as this is fixed";
      if (!message.equals(problem)) {
        problem = message;
        report.accept(message);
      }
      pending.compareAndSet(null, snap);
    } catch (RuntimeException e) {
      String message = "cannot save " + workspace.folder() + ": " + e;
      problem = message;
      report.accept(message);
    }
  }

  /** The current save problem, "" when the last save worked. */
  public String problem() {
    return problem;
  }

  /** "saved HH:MM:SS" after the last write, "" before. */
  public String status() {
    return status;
  }

  /** Saves what is left, waits for it (up to 10 s), stops the writer thread. Closing again does nothing. */
  @Override
  public void close() {
    if (writer.isShutdown()) {
      return;
    }
    if (!workspace.readOnly()) {
      saveNow(10_000);
    }
    writer.shutdown();
    try {
      writer.awaitTermination(10, TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
