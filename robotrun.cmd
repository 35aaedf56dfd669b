@echo off
rem Starts RobotRun on Windows. Builds target\robotrun.jar on first use. Needs a JDK 21+.
setlocal
set HERE=%~dp0
if not exist "%HERE%target\robotrun.jar" (
  echo robotrun: building on first use... 1>&2
  pushd "%HERE%"
  call mvnw.cmd -q -B -DskipTests package || (popd & exit /b 1)
  popd
)
set JAVA=java
if defined JAVA_HOME set JAVA="%JAVA_HOME%\bin\java"
%JAVA% --enable-native-access=ALL-UNNAMED %ROBOTRUN_JAVA_OPTS% -jar "%HERE%target\robotrun.jar" %*
