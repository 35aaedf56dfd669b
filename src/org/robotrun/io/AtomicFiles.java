package org.robotrun.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Set;

/**
 * The one way RobotRun writes a file, so that a crash never leaves it half-written.
 *
 * <p>The bytes go to a temporary file with a unique name in the target's folder (two writers
 * never collide), are forced to disk, and the temporary file is renamed over the target in one
 * atomic step; the folder is then forced too, so the rename itself survives a power cut. A new
 * file gets the permissions the user's umask gives (the temporary file is created as an
 * ordinary file would be, not with 0600); a replaced file keeps its own permissions. On any
 * failure the target is left as it was and the temporary file is removed.
 */
public final class AtomicFiles {
  private static final SecureRandom RANDOM = new SecureRandom();

  private AtomicFiles() {}

  /** Something that writes the whole content of a file to a stream. */
  @FunctionalInterface
  public interface Content {
    void writeTo(OutputStream out) throws IOException;
  }

  /** Replaces {@code target} with {@code bytes} atomically. */
  public static void write(Path target, byte[] bytes) throws IOException {
    write(target, out -> out.write(bytes));
  }

  /**
   * Replaces {@code target} with what {@code content} writes, atomically. The stream is
   * buffered by the caller's choice; it is flushed and forced to disk here.
   */
  public static void write(Path target, Content content) throws IOException {
    write(target, content, true);
  }

  /**
   * Replaces {@code target} as {@link #write(Path, byte[])} does (temporary file, forced, renamed)
   * but leaves the folder sync to the caller, who saves many files of one folder together and
   * then calls {@link #syncFolder} once. Each file is whole after a crash either way; the folder
   * sync makes the renames themselves durable.
   */
  public static void writeLeavingFolderSync(Path target, byte[] bytes) throws IOException {
    write(target, out -> out.write(bytes), false);
  }

  /** Forces a folder's entries to disk (after {@link #writeLeavingFolderSync}); a no-op where unsupported. */
  public static void syncFolder(Path dir) {
    forceFolder(dir.toAbsolutePath());
  }

  private static void write(Path target, Content content, boolean syncFolder) throws IOException {
    Path abs = target.toAbsolutePath();
    Path dir = abs.getParent();
    if (dir == null) throw new IOException(abs + ": not a file path");
    refuseSpecial(abs);
    Path tmp = createUniqueTemp(dir, abs.getFileName().toString());
    try {
      try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE);
           OutputStream out = Channels.newOutputStream(ch)) {
        content.writeTo(out);
        out.flush();
        ch.force(true);
      }
      keepPermissionsOf(abs, tmp);
      try {
        Files.move(tmp, abs, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
      } catch (AtomicMoveNotSupportedException e) {
        // Some file systems (network shares) cannot rename atomically; a plain replace is the best left.
        Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
      }
      if (syncFolder) {
        forceFolder(dir);
      }
    } finally {
      Files.deleteIfExists(tmp);
    }
  }

  /**
   * Checks, before a long job, that {@code target} could be written: its folder exists and is
   * writable, and the target is not a folder. Writes nothing that stays behind.
   *
   * @throws IOException with a message naming the path and the reason
   */
  public static void checkWritable(Path target) throws IOException {
    Path abs = target.toAbsolutePath();
    Path dir = abs.getParent();
    if (dir == null || !Files.isDirectory(dir)) throw new IOException(abs + ": the folder does not exist");
    refuseSpecial(abs);
    if (Files.exists(abs) && !Files.isWritable(abs)) throw new IOException(abs + ": the file is read-only");
    Path probe;
    try {
      probe = createUniqueTemp(dir, abs.getFileName().toString());
    } catch (IOException e) {
      String why = e instanceof java.nio.file.AccessDeniedException ? "permission denied"
          : e instanceof java.nio.file.NoSuchFileException ? "the folder cannot hold new files"
          : e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
      throw new IOException(abs + ": cannot create a file in " + dir + " (" + why + ")");
    }
    // An empty file fits on a full disk: a block written and forced does not.
    try (FileChannel ch = FileChannel.open(probe, StandardOpenOption.WRITE)) {
      ch.write(java.nio.ByteBuffer.allocate(4096));
      ch.force(true);
    } catch (IOException e) {
      Files.deleteIfExists(probe);
      String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
      throw new IOException(abs + ": cannot write in " + dir + " (" + why + ")");
    }
    Files.deleteIfExists(probe);
  }

  /**
   * Refuses a target that exists and is not a regular file: a folder, or a device or pipe
   * ({@code /dev/full}, a FIFO) that a rename would replace with a plain file.
   */
  private static void refuseSpecial(Path abs) throws IOException {
    if (Files.isDirectory(abs)) throw new IOException(abs + ": is a folder");
    if (Files.exists(abs) && !Files.isRegularFile(abs)) {
      String kind = BoundedFiles.kind(abs, Files.readAttributes(abs, java.nio.file.attribute.BasicFileAttributes.class));
      throw new IOException(abs + ": is " + kind + ", not a regular file");
    }
  }

  /** The temporary files {@link #write} makes: {@code .NAME.0123456789ab.tmp}. */
  private static final java.util.regex.Pattern TEMPORARY = java.util.regex.Pattern.compile("\\..{1,60}\\.[0-9a-f]{12}\\.tmp");

  /** Whether {@code fileName} is one of the temporary files this class makes (a crash may leave one). */
  public static boolean isTemporaryName(String fileName) {
    return fileName.length() <= 80 && TEMPORARY.matcher(fileName).matches();
  }

  /** Creates an empty, unique temporary file beside the target, with umask permissions. */
  private static Path createUniqueTemp(Path dir, String name) throws IOException {
    String base = name.length() > 60 ? name.substring(0, 60) : name;
    for (int attempt = 0; ; attempt++) {
      byte[] salt = new byte[6];
      RANDOM.nextBytes(salt);
      Path tmp = dir.resolve("." + base + "." + HexFormat.of().formatHex(salt) + ".tmp");
      try {
        // CREATE_NEW opens with mode 0666 filtered by the umask, as any new file would be.
        Files.newByteChannel(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
        return tmp;
      } catch (FileAlreadyExistsException e) {
        if (attempt > 16) throw e;
      }
    }
  }

  private static void keepPermissionsOf(Path target, Path tmp) {
    try {
      if (!Files.exists(target, LinkOption.NOFOLLOW_LINKS)) return;
      PosixFileAttributeView view = Files.getFileAttributeView(target, PosixFileAttributeView.class);
      if (view == null) return;
      Set<PosixFilePermission> perms = view.readAttributes().permissions();
      Files.setPosixFilePermissions(tmp, perms);
    } catch (IOException | UnsupportedOperationException e) {
      // Permissions are kept where the file system has them; the content matters more.
    }
  }

  /** Forces the folder's entry table to disk so the rename survives a crash (a no-op where unsupported). */
  private static void forceFolder(Path dir) {
    try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
      ch.force(true);
    } catch (IOException | UnsupportedOperationException e) {
      // Windows cannot open a folder as a channel; its rename is already durable enough.
    }
  }
}
