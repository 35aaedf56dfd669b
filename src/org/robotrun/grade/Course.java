package org.robotrun.grade;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Pattern;
import org.robotrun.io.JsonFieldReader;
import org.robotrun.io.LocatedJson;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.io.ScenarioError;

/**
 * A course: a folder of labs listed in {@code course.json} (docs/labs/README.md). Each lab names
 * its starting cell, its graded task and its guide, relative to the course file. Read as strictly
 * as a task: an unknown field, a missing file or a duplicate id is an error with line and path.
 *
 * @param file the course.json read
 * @param title shown over the list of labs
 * @param labs in the order given
 */
public record Course(Path file, String title, List<Lab> labs) {
  public static final int FORMAT = 1;
  /** A lab id: it names the lab's folder and the student's workspace for it. */
  public static final Pattern ID = Pattern.compile("[A-Za-z0-9][A-Za-z0-9_.-]{0,63}");

  public Course {
    labs = List.copyOf(labs);
  }

  /**
   * One lab.
   *
   * @param id the lab's folder name and the student's workspace name
   * @param hours planned lab time
   * @param prerequisites ids of the labs before it
   * @param assesses what the task grades, in words
   */
  public record Lab(String id, String title, double hours, List<String> prerequisites, String assesses, Path guide,
      Path cell, Path task) {
    public Lab {
      prerequisites = List.copyOf(prerequisites);
    }
  }

  /** Thrown with every problem of a course file, one per line as {@code file:line: path: message}. */
  public static final class CourseException extends Exception {
    private static final long serialVersionUID = 1L;

    CourseException(List<ScenarioError> errors) {
      super(String.join("\n", errors.stream().map(ScenarioError::toString).toList()));
    }
  }

  /** The lab with this id. */
  public Optional<Lab> lab(String id) {
    return labs.stream().filter(l -> l.id().equals(id)).findFirst();
  }

  /** Reads {@code course.json} (or the course.json in a folder). */
  public static Course read(Path fileOrFolder) throws CourseException {
    Path file = Files.isDirectory(fileOrFolder) ? fileOrFolder.resolve("course.json") : fileOrFolder;
    String text;
    try {
      byte[] bytes = org.robotrun.io.BoundedFiles.read(file, 1L << 20, "course files");
      text = StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes)).toString();
    } catch (org.robotrun.io.UnreadableFileException e) {
      throw new CourseException(List.of(new ScenarioError(file.toString(), 0, "", e.getMessage())));
    } catch (CharacterCodingException e) {
      throw new CourseException(List.of(new ScenarioError(file.toString(), 0, "", "not UTF-8 text")));
    } catch (IOException e) {
      throw new CourseException(List.of(new ScenarioError(file.toString(), 0, "", "cannot read: " + e.getMessage())));
    }
    return new Session(file).read(text);
  }

  private static final class Session extends JsonFieldReader {
    private static final Set<String> TOP = Set.of("format", "title", "labs");
    private static final Set<String> LAB = Set.of("id", "title", "hours", "prerequisites", "assesses", "guide", "cell",
        "task");
    private final Path path;

    Session(Path file) {
      super(file.toString());
      this.path = file.toAbsolutePath().normalize();
    }

    Course read(String text) throws CourseException {
      JObject top = topObject(text, TOP);
      if (top == null) {
        throw new CourseException(errors);
      }
      format(top, FORMAT);
      String title = string(top, "title", "", false).orElse("");
      List<Lab> labs = new ArrayList<>();
      JArray arr = array(top, "labs", "", true);
      Set<String> ids = new HashSet<>();
      for (int i = 0; arr != null && i < arr.items().size(); i++) {
        String at = "labs[" + i + "]";
        JObject o = object(arr.items().get(i), at, LAB);
        if (o == null) {
          continue;
        }
        String id = string(o, "id", at, true).orElse("");
        if (!id.isEmpty() && !ID.matcher(id).matches()) {
          error(o.line(), at + ".id", "expected letters, digits, '-', '_' or '.' (it names a folder), got \"" + id + "\"");
        } else if (!id.isEmpty() && !ids.add(id)) {
          error(o.line(), at + ".id", "\"" + id + "\" is used twice");
        }
        double hours = number(o, "hours", at, false, 0, 1000, 0);
        List<String> pre = new ArrayList<>();
        if (o.members().get("prerequisites") instanceof JArray p) {
          for (LocatedJson v : p.items()) {
            if (v instanceof LocatedJson.JString s) {
              pre.add(s.value());
            } else {
              error(v.line(), at + ".prerequisites", "expected lab ids (strings)");
            }
          }
        }
        labs.add(new Lab(id, string(o, "title", at, true).orElse(id), hours, pre,
            string(o, "assesses", at, false).orElse(""), file(o, "guide", at), file(o, "cell", at), file(o, "task", at)));
      }
      if (!errors.isEmpty()) {
        throw new CourseException(errors);
      }
      return new Course(path, title, labs);
    }

    private Path file(JObject o, String key, String at) {
      Optional<String> rel = string(o, key, at, true);
      if (rel.isEmpty()) {
        return path;
      }
      try {
        Path p = path.getParent().resolve(rel.get()).normalize();
        if (!Files.isRegularFile(p)) {
          error(o.members().get(key).line(), join(at, key), "file not found: " + p + " (paths are relative to course.json)");
        }
        return p;
      } catch (java.nio.file.InvalidPathException e) {
        error(o.members().get(key).line(), join(at, key), "not a valid path: \"" + rel.get() + "\"");
        return path;
      }
    }
  }
}
