package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Where the hand-in is in what a platform hands over, and the student's name from Gradescope. */
class AutograderRunCommandTest {
  @TempDir Path dir;

  @Test
  void anUnpackedHandInIsTheFolderItselfAndAZipOfAFolderIsLookedInto() throws Exception {
    Path sub = Files.createDirectories(dir.resolve("submission"));
    Files.createDirectories(sub.resolve("__MACOSX/ada"));
    Files.writeString(sub.resolve(".DS_Store"), "x");
    Path inner = Files.createDirectories(sub.resolve("ada"));
    Files.writeString(inner.resolve("manifest.json"), "{}");
    List<String> notes = new ArrayList<>();
    assertThat(AutograderRunCommand.locate(sub, notes)).isEqualTo(inner);
    Files.writeString(sub.resolve("manifest.json"), "{}");
    assertThat(AutograderRunCommand.locate(sub, notes)).isEqualTo(sub);
    assertThat(notes).isEmpty();
  }

  @Test
  void theOneZipIsGradedBesideOtherFilesAndSeveralZipsAreRefused() throws Exception {
    Path repo = Files.createDirectories(dir.resolve("repo"));
    Files.createDirectories(repo.resolve(".git/objects"));
    Files.createDirectories(repo.resolve(".robotrun"));
    Files.writeString(repo.resolve(".robotrun/task.zip"), "not the student's");
    Files.writeString(repo.resolve("README.md"), "# Lab");
    Files.writeString(repo.resolve("hand-in.zip"), "PK");
    List<String> notes = new ArrayList<>();
    assertThat(AutograderRunCommand.locate(repo, notes)).isEqualTo(repo.resolve("hand-in.zip"));
    assertThat(notes).containsExactly("Graded hand-in.zip (the one .zip handed in).");
    Files.writeString(repo.resolve("old.zip"), "PK");
    assertThatThrownBy(() -> AutograderRunCommand.locate(repo, notes))
        .hasMessage("Several .zip files were handed in (hand-in.zip, old.zip): hand in only the one .zip that "
            + "File > Hand in writes.");
  }

  @Test
  void programsAloneAreGradedAndNothingIsSaidSo() throws Exception {
    Path sub = Files.createDirectories(dir.resolve("student"));
    Files.writeString(sub.resolve("PICKPLACE.LS"), "/PROG PICKPLACE\n/MN\n/END\n");
    assertThat(AutograderRunCommand.locate(sub, new ArrayList<>())).isEqualTo(sub);
    Path empty = Files.createDirectories(dir.resolve("empty"));
    Files.writeString(empty.resolve("notes.txt"), "later");
    assertThatThrownBy(() -> AutograderRunCommand.locate(empty, new ArrayList<>()))
        .hasMessageStartingWith("No hand-in was found in what was handed in (notes.txt)");
    assertThatThrownBy(() -> AutograderRunCommand.locate(dir.resolve("none"), new ArrayList<>()))
        .hasMessageContaining("does not exist: nothing was handed in");
  }

  @Test
  void gradescopeMetadataGivesEveryGroupMembersNameAndAnythingElseGivesNone() throws Exception {
    Path m = dir.resolve("submission_metadata.json");
    Files.writeString(m, "{\"users\": [{\"name\": \"Ada Lovelace\"}, {\"name\": \" Bob \"}, {\"email\": \"x@y\"}]}");
    assertThat(AutograderRunCommand.gradescopeStudents(m)).isEqualTo("Ada Lovelace, Bob");
    Files.writeString(m, "{\"users\": ");
    assertThat(AutograderRunCommand.gradescopeStudents(m)).isEmpty();
    assertThat(AutograderRunCommand.gradescopeStudents(dir.resolve("missing.json"))).isEmpty();
  }
}
