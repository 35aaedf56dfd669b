package org.robotrun.ui;

import static org.lwjgl.util.nfd.NativeFileDialog.*;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.lwjgl.PointerBuffer;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.util.nfd.NFDFilterItem;

/**
 * The system's own file dialogs through LWJGL's nativefiledialog binding (GTK or the desktop
 * portal on Linux, the usual dialogs on Windows and macOS). Where none can be shown (no GTK, a
 * bare X server), every call answers {@link Answer.Unavailable} with the reason, and the File
 * menu asks for a typed path instead. Call from the window's thread only.
 */
public final class FileDialogs {
  private boolean tried;
  private String unavailable = "";

  /** What a dialog gave. */
  public sealed interface Answer {
    record Chosen(List<Path> paths) implements Answer {}

    record Cancelled() implements Answer {}

    record Unavailable(String reason) implements Answer {}
  }

  private boolean ready() {
    if (!tried) {
      tried = true;
      if (System.getenv("ROBOTRUN_NO_NATIVE_DIALOGS") != null) {
        unavailable = "native dialogs are switched off (ROBOTRUN_NO_NATIVE_DIALOGS)";
        return false;
      }
      try {
        if (NFD_Init() != NFD_OKAY) {
          unavailable = "the system file dialog could not start (" + NFD_GetError() + ")";
        }
      } catch (Throwable e) {  // a missing GTK shows as a link error when the library loads
        unavailable = "no system file dialog on this machine (" + e.getClass().getSimpleName() + ": " + e.getMessage() + ")";
      }
    }
    return unavailable.isEmpty();
  }

  /** Picks a folder. */
  public Answer pickFolder(Path start) {
    if (!ready()) {
      return new Answer.Unavailable(unavailable);
    }
    try (MemoryStack stack = MemoryStack.stackPush()) {
      PointerBuffer out = stack.mallocPointer(1);
      return single(NFD_PickFolder(out, start == null ? null : start.toString()), out);
    }
  }

  /** Picks one file (or several with {@code many}) whose extension is one of {@code extensions} (e.g. "LS,ls"). */
  public Answer open(String filterName, String extensions, boolean many, Path start) {
    if (!ready()) {
      return new Answer.Unavailable(unavailable);
    }
    try (MemoryStack stack = MemoryStack.stackPush()) {
      NFDFilterItem.Buffer filters = NFDFilterItem.malloc(1, stack);
      filters.get(0).name(stack.UTF8(filterName)).spec(stack.UTF8(extensions));
      PointerBuffer out = stack.mallocPointer(1);
      String dir = start == null ? null : start.toString();
      if (!many) {
        return single(NFD_OpenDialog(out, filters, dir), out);
      }
      int r = NFD_OpenDialogMultiple(out, filters, dir);
      if (r != NFD_OKAY) {
        return r == NFD_CANCEL ? new Answer.Cancelled() : new Answer.Unavailable(String.valueOf(NFD_GetError()));
      }
      long set = out.get(0);
      int[] count = new int[1];
      NFD_PathSet_GetCount(set, count);
      List<Path> paths = new ArrayList<>();
      PointerBuffer one = stack.mallocPointer(1);
      for (int i = 0; i < count[0]; i++) {
        if (NFD_PathSet_GetPath(set, i, one) == NFD_OKAY) {
          paths.add(Path.of(one.getStringUTF8(0)));
          NFD_PathSet_FreePath(one.get(0));
        }
      }
      NFD_PathSet_Free(set);
      return new Answer.Chosen(paths);
    }
  }

  /** Asks for a file to write; the dialog itself asks before replacing an existing file. */
  public Answer save(String filterName, String extensions, Path start, String defaultName) {
    if (!ready()) {
      return new Answer.Unavailable(unavailable);
    }
    try (MemoryStack stack = MemoryStack.stackPush()) {
      NFDFilterItem.Buffer filters = NFDFilterItem.malloc(1, stack);
      filters.get(0).name(stack.UTF8(filterName)).spec(stack.UTF8(extensions));
      PointerBuffer out = stack.mallocPointer(1);
      return single(NFD_SaveDialog(out, filters, start == null ? null : start.toString(), defaultName), out);
    }
  }

  private static Answer single(int r, PointerBuffer out) {
    if (r == NFD_CANCEL) {
      return new Answer.Cancelled();
    }
    if (r != NFD_OKAY) {
      return new Answer.Unavailable(String.valueOf(NFD_GetError()));
    }
    Path p = Path.of(out.getStringUTF8(0));
    NFD_FreePath(out.get(0));
    return new Answer.Chosen(List.of(p));
  }

  /** Releases the dialog library. */
  public void close() {
    if (tried && unavailable.isEmpty()) {
      NFD_Quit();
    }
  }
}
