package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicFilesTest {
  @TempDir Path dir;

  private static boolean posix() {
    return FileSystems.getDefault().supportedFileAttributeViews().contains("posix");
  }

  @Test
  void replacedFileKeepsItsPermissions() throws IOException {
    assumeTrue(posix(), "POSIX permissions only");
    Path f = dir.resolve("A.LS");
    Files.writeString(f, "old");
    Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r-----"));
    AtomicFiles.write(f, "new".getBytes(StandardCharsets.UTF_8));
    assertThat(Files.readString(f)).isEqualTo("new");
    assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(f))).isEqualTo("rw-r-----");
  }

  @Test
  void newFileGetsUmaskPermissionsNotPrivateTempPermissions() throws IOException {
    assumeTrue(posix(), "POSIX permissions only");
    // A plain new file shows what the umask gives here; the atomic writer must match it.
    Path plain = dir.resolve("plain");
    Files.newByteChannel(plain, java.nio.file.StandardOpenOption.CREATE_NEW, java.nio.file.StandardOpenOption.WRITE).close();
    Path f = dir.resolve("B.LS");
    AtomicFiles.write(f, new byte[] {1, 2, 3});
    assertThat(Files.getPosixFilePermissions(f)).isEqualTo(Files.getPosixFilePermissions(plain));
  }

  @Test
  void aFailingWriterLeavesTheOldFileAndNoTemporaryFile() throws IOException {
    Path f = dir.resolve("C.LS");
    Files.writeString(f, "keep me");
    assertThatThrownBy(() -> AtomicFiles.write(f, out -> {
      out.write("half".getBytes(StandardCharsets.UTF_8));
      throw new IOException("disk full");
    })).hasMessageContaining("disk full");
    assertThat(Files.readString(f)).isEqualTo("keep me");
    try (var s = Files.list(dir)) {
      assertThat(s.map(p -> p.getFileName().toString())).containsExactly("C.LS");
    }
  }

  @Test
  void concurrentWritersToOneFileNeverCollideOrMix() throws Exception {
    Path f = dir.resolve("report.json");
    ExecutorService pool = Executors.newFixedThreadPool(4);
    try {
      List<Future<?>> jobs = new ArrayList<>();
      for (int i = 0; i < 40; i++) {
        byte[] body = ("writer " + i + " ").repeat(2000).getBytes(StandardCharsets.UTF_8);
        jobs.add(pool.submit(() -> { AtomicFiles.write(f, body); return null; }));
      }
      for (Future<?> j : jobs) j.get();
    } finally {
      pool.shutdown();
    }
    String text = Files.readString(f);
    String first = text.substring(0, text.indexOf(' ', 7) + 1);
    assertThat(text).isEqualTo(first.repeat(2000));
    try (var s = Files.list(dir)) {
      assertThat(s.count()).isEqualTo(1);
    }
  }

  @Test
  void aFolderAsTargetOrAMissingFolderIsAClearError() throws IOException {
    Path sub = Files.createDirectory(dir.resolve("sub"));
    assertThatThrownBy(() -> AtomicFiles.write(sub, new byte[0])).hasMessageContaining("is a folder");
    assertThatThrownBy(() -> AtomicFiles.checkWritable(dir.resolve("nope/x.json")))
        .hasMessageContaining("does not exist");
    AtomicFiles.checkWritable(dir.resolve("ok.json"));
    assertThat(Files.exists(dir.resolve("ok.json"))).isFalse();
  }
}
