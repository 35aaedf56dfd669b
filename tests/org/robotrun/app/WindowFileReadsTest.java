package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInException;
import org.robotrun.io.UserDirs;
import org.robotrun.io.Workspace;

/**
 * Issue 18: the files the window reads besides scenarios, programs and meshes (the workspace's
 * own files when it is copied or handed in, the recent-workspace list, a task) are bounded and
 * regular files only: a FIFO is named and never blocks, a huge file is refused unread.
 */
@EnabledOnOs({OS.LINUX, OS.MAC})
@Timeout(value = 20, unit = TimeUnit.SECONDS)
class WindowFileReadsTest {
  @TempDir Path dir;

  private static void fifo(Path f) throws Exception {
    Process p = new ProcessBuilder("mkfifo", f.toString()).start();
    assertThat(p.waitFor()).isZero();
  }

  private Path workspace() throws Exception {
    Path ws = dir.resolve("ws");
    Workspace.open(ws, WorkspaceSession.newCell()).close();
    return ws;
  }

  @Test
  void savingACopyOfAWorkspaceWhoseCellIsAFifoSaysSoAndDoesNotBlock() throws Exception {
    Path ws = workspace();
    Files.delete(ws.resolve(Workspace.CELL));
    fifo(ws.resolve(Workspace.CELL));
    String problem = WorkspaceFiles.saveCopy(ws, dir.resolve("copy"));
    assertThat(problem).contains(ws.resolve(Workspace.CELL) + ": a named pipe (FIFO), not a regular file");
  }

  @Test
  void handingInAWorkspaceWithAFifoOrAHugeProgramIsRefusedByName() throws Exception {
    Path ws = workspace();
    Path big = ws.resolve("programs/BIG.LS");
    try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
      f.setLength(3L << 30);  // sparse: 3 GiB declared, nothing on disk
    }
    assertThatThrownBy(() -> HandIn.write(ws, dir.resolve("h.zip"), "me", "test", false))
        .isInstanceOf(HandInException.class)
        .hasMessageContaining(big + ": file is 3072.0 MiB; .LS programs are limited to 16 MiB");
    Files.delete(big);
    Files.delete(ws.resolve(Workspace.CELL));
    fifo(ws.resolve(Workspace.CELL));
    assertThatThrownBy(() -> HandIn.write(ws, dir.resolve("h.zip"), "me", "test", false))
        .isInstanceOf(HandInException.class)
        .hasMessageContaining("a named pipe (FIFO), not a regular file");
    assertThat(dir.resolve("h.zip")).doesNotExist();
  }

  @Test
  void openingAHandInThatIsAFifoSaysSo() throws Exception {
    Path zip = dir.resolve("h.zip");
    fifo(zip);
    assertThatThrownBy(() -> HandIn.unpack(zip, Files.createDirectories(dir.resolve("into"))))
        .isInstanceOf(HandInException.class)
        .hasMessage(zip + ": a named pipe (FIFO), not a regular file");
  }

  @Test
  void aRecentListThatIsAFifoOrNotUtf8IsNoTrouble() throws Exception {
    Path config = Files.createDirectories(dir.resolve("config"));
    UserDirs dirs = new UserDirs(dir.resolve("data"), config);
    fifo(config.resolve("recent-workspaces.txt"));
    assertThat(dirs.recentWorkspaces()).isEmpty();
    Files.delete(config.resolve("recent-workspaces.txt"));
    Path ws = Files.createDirectories(dir.resolve("w1"));
    Files.write(config.resolve("recent-workspaces.txt"),
        ("\u00ff\u00fe\n" + ws.toAbsolutePath() + "\n").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
    assertThat(dirs.recentWorkspaces()).containsExactly(ws.toAbsolutePath());
  }

  @Test
  void aTaskFileThatIsAFifoIsNamed() throws Exception {
    Path task = dir.resolve("t.task.json");
    fifo(task);
    TaskLoad l = TaskReader.read(task);
    assertThat(l).isInstanceOf(TaskLoad.Failed.class);
    assertThat(((TaskLoad.Failed) l).errors().getFirst().message()).isEqualTo("a named pipe (FIFO), not a regular file");
  }
}
