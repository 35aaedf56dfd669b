package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;

/** A linked GLSL program loaded from {@code resources/shaders/}. */
final class ShaderProgram implements AutoCloseable {
  private final int id;
  private final Map<String, Integer> uniforms = new HashMap<>();

  private ShaderProgram(int id) {
    this.id = id;
  }

  static ShaderProgram load(String name) {
    int vs = compile(GL_VERTEX_SHADER, read("/shaders/" + name + ".vert"), name + ".vert");
    int fs = compile(GL_FRAGMENT_SHADER, read("/shaders/" + name + ".frag"), name + ".frag");
    int prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    glBindAttribLocation(prog, 0, "aPosition");
    glBindAttribLocation(prog, 1, "aNormal");
    glLinkProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    if (glGetProgrami(prog, GL_LINK_STATUS) == GL_FALSE) {
      throw new IllegalStateException("shader " + name + " failed to link: " + glGetProgramInfoLog(prog));
    }
    return new ShaderProgram(prog);
  }

  private static int compile(int type, String src, String what) {
    int s = glCreateShader(type);
    glShaderSource(s, src);
    glCompileShader(s);
    if (glGetShaderi(s, GL_COMPILE_STATUS) == GL_FALSE) {
      throw new IllegalStateException("shader " + what + " failed to compile: " + glGetShaderInfoLog(s));
    }
    return s;
  }

  private static String read(String path) {
    try (InputStream in = ShaderProgram.class.getResourceAsStream(path)) {
      if (in == null) {
        throw new IllegalStateException("missing shader resource " + path);
      }
      return new String(in.readAllBytes(), StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new IllegalStateException("cannot read shader " + path, e);
    }
  }

  void use() {
    glUseProgram(id);
  }

  int uniform(String name) {
    return uniforms.computeIfAbsent(name, n -> glGetUniformLocation(id, n));
  }

  @Override
  public void close() {
    glDeleteProgram(id);
  }
}
