package org.robotrun.io;

import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * Files that arrive with a hand-in but are not part of it: what an operating system drops into
 * a folder or a zip it makes ({@code __MACOSX/}, {@code ._NAME} AppleDouble files,
 * {@code .DS_Store}, {@code Thumbs.db}, {@code desktop.ini}) and what a course platform keeps
 * beside a student's files (a git checkout's {@code .git/} and {@code .github/}, the autograder
 * bundle's own {@code .robotrun/}, Gradescope's {@code submission_metadata.json}). The hand-in
 * check ignores them and lists them; it does not fail for them (docs/grading.md). The one place
 * this rule is written: every reader of hand-ins, zipped or unpacked, asks here.
 */
public final class HandInDroppings {
  /** Folders whose whole content is ignored, at any depth. */
  private static final Set<String> FOLDERS = Set.of("__macosx", ".git", ".github", ".robotrun");
  /** File names ignored at any depth (compared ignoring case, as the systems that write them do). */
  private static final Set<String> FILES = Set.of(".ds_store", "thumbs.db", "desktop.ini", "submission_metadata.json",
      ".gitignore", ".gitattributes");

  private HandInDroppings() {}

  /**
   * Whether a file inside a hand-in is a dropping, by its path relative to the hand-in's root
   * ({@code /}-separated, as a zip entry names it).
   */
  public static boolean isDropping(String relPath) {
    String path = relPath.replace('\\', '/');
    boolean folder = path.endsWith("/");  // a zip's folder entry
    String[] parts = path.split("/");
    for (int i = 0; i < parts.length; i++) {
      String p = parts[i].toLowerCase(Locale.ROOT);
      boolean last = i == parts.length - 1 && !folder;
      if (!last && (FOLDERS.contains(p) || p.startsWith("._"))) {
        return true;
      }
      if (last && (FILES.contains(p) || p.startsWith("._"))) {
        return true;
      }
    }
    return false;
  }

  /** The note a hand-in check shows for the droppings found ("" when none), at most 10 named. */
  public static String note(List<String> droppings) {
    if (droppings.isEmpty()) {
      return "";
    }
    List<String> shown = droppings.stream().limit(10).map(TerminalText::safe).toList();
    return "ignored (operating system or platform files, not part of the hand-in): " + String.join(", ", shown)
        + (droppings.size() > 10 ? " and " + (droppings.size() - 10) + " more" : "");
  }
}
