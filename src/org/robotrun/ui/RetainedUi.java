package org.robotrun.ui;

import static org.lwjgl.opengl.GL33C.*;

import imgui.ImDrawData;
import imgui.ImGui;
import imgui.ImGuiIO;
import imgui.type.ImInt;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import org.robotrun.render.DamageRegion;

/**
 * Draws Dear ImGui's panels with OpenGL 3.3, only where they changed. Each frame the draw lists
 * are copied ({@link DrawListCopy}) and compared with the last frame's, list by list in drawing
 * order: a list that changed damages the parts of the screen it changed in (a changed number:
 * its changed glyphs, each changed line apart; a list that appeared, went or changed its
 * commands: all it draws), and a list that shows a texture other than the font (a camera image,
 * whose pixels may change while its list does not) damages its image every frame. The window
 * then draws each damaged rectangle again, and {@link #draw} draws every list that reaches into
 * it, clipped to it, in ImGui's order.
 *
 * <p>The drawing follows Dear ImGui's documented rendering contract (docs/FAQ and imgui.h's
 * ImDrawData notes): an orthographic projection of the display rectangle, alpha blending of
 * straight colours, per command a scissor from its clip rectangle and its texture, indices per
 * command from its index offset with its vertex offset as base vertex.
 */
final class RetainedUi implements AutoCloseable {
  private static final String VERTEX = """
      #version 330 core
      in vec2 aPos;
      in vec2 aUv;
      in vec4 aColor;
      uniform mat4 uProj;
      out vec2 vUv;
      out vec4 vColor;
      void main() {
        vUv = aUv;
        vColor = aColor;
        gl_Position = uProj * vec4(aPos, 0.0, 1.0);
      }
      """;
  private static final String FRAGMENT = """
      #version 330 core
      in vec2 vUv;
      in vec4 vColor;
      uniform sampler2D uTex;
      out vec4 fragColor;
      void main() {
        fragColor = vColor * texture(uTex, vUv);
      }
      """;
  /** ImGuiBackendFlags_RendererHasVtxOffset: lists of more than 64k vertices use base vertices. */
  private static final int HAS_VTX_OFFSET = 1 << 3;

  private final int program;
  private final int uProj;
  private final int uTex;
  private final int vao;
  private final int vbo;
  private final int ebo;
  private final int fontTexture;
  private List<DrawListCopy> lists = new ArrayList<>();
  private List<DrawListCopy> previous = new ArrayList<>();
  private int count;
  private int previousCount;
  private final imgui.ImVec4 clipOut = new imgui.ImVec4();
  private float dispX;
  private float dispY;
  private float dispW;
  private float dispH;
  private float scaleX = 1;
  private float scaleY = 1;
  private int fbH;
  private int fbW;
  /** Which list's vertices and indices are in the buffers now (-1: none this frame). */
  private int uploaded = -1;

  RetainedUi() {
    program = link(compile(GL_VERTEX_SHADER, VERTEX), compile(GL_FRAGMENT_SHADER, FRAGMENT));
    uProj = glGetUniformLocation(program, "uProj");
    uTex = glGetUniformLocation(program, "uTex");
    vao = glGenVertexArrays();
    vbo = glGenBuffers();
    ebo = glGenBuffers();
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(0, 2, GL_FLOAT, false, DrawListCopy.VERT_BYTES, 0);
    glVertexAttribPointer(1, 2, GL_FLOAT, false, DrawListCopy.VERT_BYTES, 8);
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, true, DrawListCopy.VERT_BYTES, 16);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    ImGuiIO io = ImGui.getIO();
    io.setBackendRendererName("robotrun_retained_gl3");
    io.addBackendFlags(HAS_VTX_OFFSET);
    ImInt w = new ImInt(), h = new ImInt();
    ByteBuffer pixels = io.getFonts().getTexDataAsRGBA32(w, h);
    fontTexture = glGenTextures();
    glBindTexture(GL_TEXTURE_2D, fontTexture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w.get(), h.get(), 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glBindTexture(GL_TEXTURE_2D, 0);
    io.getFonts().setTexID(fontTexture);
  }

  private static int compile(int type, String source) {
    int s = glCreateShader(type);
    glShaderSource(s, source);
    glCompileShader(s);
    if (glGetShaderi(s, GL_COMPILE_STATUS) == GL_FALSE) {
      throw new IllegalStateException("the panels' shader failed to compile: " + glGetShaderInfoLog(s));
    }
    return s;
  }

  private static int link(int vs, int fs) {
    int p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glBindAttribLocation(p, 0, "aPos");
    glBindAttribLocation(p, 1, "aUv");
    glBindAttribLocation(p, 2, "aColor");
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    if (glGetProgrami(p, GL_LINK_STATUS) == GL_FALSE) {
      throw new IllegalStateException("the panels' shader failed to link: " + glGetProgramInfoLog(p));
    }
    return p;
  }

  /** Copies this frame's draw data (after ImGui.render) for a framebuffer of fbW × fbH pixels. */
  void capture(ImDrawData data, int framebufferWidth, int framebufferHeight) {
    List<DrawListCopy> t = previous;
    previous = lists;
    lists = t;
    previousCount = count;
    uploaded = -1;
    fbW = framebufferWidth;
    fbH = framebufferHeight;
    dispX = data.getDisplayPosX();
    dispY = data.getDisplayPosY();
    dispW = data.getDisplaySizeX();
    dispH = data.getDisplaySizeY();
    scaleX = data.getFramebufferScaleX();
    scaleY = data.getFramebufferScaleY();
    if (!(scaleX > 0) || !(scaleY > 0)) {
      scaleX = dispW > 0 ? fbW / dispW : 1;
      scaleY = dispH > 0 ? fbH / dispH : 1;
    }
    count = data.getValid() ? data.getCmdListsCount() : 0;
    int idxBytes = ImDrawData.sizeOfImDrawIdx();
    for (int i = 0; i < count; i++) {
      if (lists.size() <= i) {
        lists.add(new DrawListCopy());
      }
      DrawListCopy c = lists.get(i);
      int nv = data.getCmdListVtxBufferSize(i);
      int ni = data.getCmdListIdxBufferSize(i);
      int nc = data.getCmdListCmdBufferSize(i);
      c.reserve(nv, ni, idxBytes, nc);
      copy(data.getCmdListVtxBufferData(i), c.vtx, nv * DrawListCopy.VERT_BYTES);
      copy(data.getCmdListIdxBufferData(i), c.idx, ni * idxBytes);
      for (int k = 0; k < nc; k++) {
        // clip rectangles in display coordinates, as ImGui gives them
        data.getCmdListCmdBufferClipRect(i, k, clipOut);
        c.clip[4 * k] = clipOut.x;
        c.clip[4 * k + 1] = clipOut.y;
        c.clip[4 * k + 2] = clipOut.z;
        c.clip[4 * k + 3] = clipOut.w;
        c.texture[k] = data.getCmdListCmdBufferTextureId(i, k);
        c.elemCount[k] = data.getCmdListCmdBufferElemCount(i, k);
        c.idxOffset[k] = data.getCmdListCmdBufferIdxOffset(i, k);
        c.vtxOffset[k] = data.getCmdListCmdBufferVtxOffset(i, k);
      }
    }
  }

  private static void copy(ByteBuffer from, ByteBuffer to, int bytes) {
    to.clear();
    to.put(0, from, 0, bytes);
  }

  /**
   * Adds to {@code damage} (GL pixels) what changed since the last frame: see the class comment.
   * The first frame, or a different display size, damages everything.
   */
  void addDamage(DamageRegion damage) {
    int n = Math.max(count, previousCount);
    for (int i = 0; i < n; i++) {
      DrawListCopy now = i < count ? lists.get(i) : null;
      DrawListCopy old = i < previousCount ? previous.get(i) : null;
      if (now == null) {
        addDisplayRect(damage, old.drawnBounds());
      } else if (old == null) {
        addDisplayRect(damage, now.drawnBounds());
      } else {
        for (float[] area : DrawListCopy.changedAreas(old, now)) {
          addDisplayRect(damage, area);
        }
      }
      if (now != null) {
        for (int k = 0; k < now.cmdCount; k++) {
          if (now.texture[k] != fontTexture) {
            addDisplayRect(damage, new float[] {now.clip[4 * k], now.clip[4 * k + 1], now.clip[4 * k + 2], now.clip[4 * k + 3]});
          }
        }
      }
    }
  }

  private void addDisplayRect(DamageRegion damage, float[] a) {
    if (a != null) {
      int[] r = toPixels(a);
      damage.add(r[0], r[1], r[2], r[3]);
    }
  }

  /** A display-coordinate rectangle {x0, y0, x1, y1} (y down) as GL pixels {x0, y0, x1, y1} (y up), grown to whole pixels. */
  private int[] toPixels(float[] a) {
    int x0 = (int) Math.floor((a[0] - dispX) * scaleX);
    int x1 = (int) Math.ceil((a[2] - dispX) * scaleX);
    int y0 = fbH - (int) Math.ceil((a[3] - dispY) * scaleY);
    int y1 = fbH - (int) Math.floor((a[1] - dispY) * scaleY);
    return new int[] {x0, y0, x1, y1};
  }

  /** Draws every list that reaches into {@code rect} (GL pixels {x0, y0, x1, y1}), clipped to it, into the bound framebuffer. */
  void draw(int[] rect) {
    if (count == 0 || dispW <= 0 || dispH <= 0) {
      return;
    }
    glViewport(0, 0, fbW, fbH);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_SCISSOR_TEST);
    glUseProgram(program);
    glUniform1i(uTex, 0);
    float l = dispX, r = dispX + dispW, t = dispY, b = dispY + dispH;
    float[] ortho = {
      2f / (r - l), 0, 0, 0,
      0, 2f / (t - b), 0, 0,
      0, 0, -1, 0,
      (r + l) / (l - r), (t + b) / (b - t), 0, 1
    };
    glUniformMatrix4fv(uProj, false, ortho);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(vao);
    int type = ImDrawData.sizeOfImDrawIdx() == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
    for (int i = 0; i < count; i++) {
      DrawListCopy c = lists.get(i);
      float[] cb = c.clipBounds();
      if (cb == null) {
        continue;
      }
      int[] reach = DamageRegion.intersect(toPixels(cb), rect);
      if (reach == null) {
        continue;
      }
      if (uploaded != i) {
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glBufferData(GL_ARRAY_BUFFER, c.vtx.slice(0, c.vtxCount * DrawListCopy.VERT_BYTES), GL_STREAM_DRAW);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, c.idx.slice(0, c.idxCount * c.idxBytes), GL_STREAM_DRAW);
        uploaded = i;
      }
      for (int k = 0; k < c.cmdCount; k++) {
        if (c.elemCount[k] == 0) {
          continue;
        }
        int[] s = DamageRegion.intersect(toPixels(new float[] {c.clip[4 * k], c.clip[4 * k + 1], c.clip[4 * k + 2], c.clip[4 * k + 3]}), rect);
        if (s == null) {
          continue;
        }
        glScissor(s[0], s[1], s[2] - s[0], s[3] - s[1]);
        glBindTexture(GL_TEXTURE_2D, c.texture[k]);
        glDrawElementsBaseVertex(GL_TRIANGLES, c.elemCount[k], type, (long) c.idxOffset[k] * c.idxBytes, c.vtxOffset[k]);
      }
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
  }

  @Override
  public void close() {
    glDeleteTextures(fontTexture);
    glDeleteBuffers(vbo);
    glDeleteBuffers(ebo);
    glDeleteVertexArrays(vao);
    glDeleteProgram(program);
  }
}
