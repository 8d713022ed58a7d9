package ray.course;

import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClasspathRoots;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.engine.support.descriptor.MethodSource;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

/**
 * The course's default-package classes (the reference solution, the stubbed handout, the student tests)
 * loaded apart from the engine: the engine has a default-package {@code RayTracer} too. Built by
 * {@code gradle courseKit} (a dependency of the test task) into build/.
 */
final class Course {

    static final Path SOLUTION_CLASSES = Paths.get("build/classes/java/courseSolution");
    static final Path TEST_CLASSES = Paths.get("build/classes/java/courseTests");
    static final Path SOLUTION_SOURCES = Paths.get("src/course/solution/java");
    static final Path HANDOUT = Paths.get("build/handout");
    static final Path KIT = Paths.get("build/course-kit");

    private Course() {
    }

    /**
     * A class loader over {@code dirs} that takes only the JDK, vecmath and JUnit from the test's own class
     * path; every other class (RayTracer, Scene, the tests) comes from {@code dirs}.
     */
    static ClassLoader loader(Path... dirs) {
        URL[] urls = new URL[dirs.length];
        for (int i = 0; i < dirs.length; i++) {
            try {
                urls[i] = dirs[i].toAbsolutePath().toUri().toURL();
            } catch (MalformedURLException e) {
                throw new IllegalArgumentException(e);
            }
        }
        ClassLoader shared = Course.class.getClassLoader();
        return new URLClassLoader(urls, ClassLoader.getPlatformClassLoader()) {
            @Override
            protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
                if (name.startsWith("javax.vecmath.") || name.startsWith("org.junit.") || name.startsWith("org.opentest4j.")
                        || name.startsWith("org.apiguardian.")) {
                    return shared.loadClass(name);
                }
                return super.loadClass(name, resolve);
            }
        };
    }

    /** One test's outcome: its class (simple name), method, status and failure message. */
    record Outcome(String testClass, String test, TestExecutionResult.Status status, String message, Throwable failure) {
    }

    /**
     * Runs the JUnit tests found in {@code testRoot} with {@code loader} as the classes' loader, with the
     * given system properties set for the run; returns every test's outcome (skipped ones too, as ABORTED).
     */
    static List<Outcome> runTests(ClassLoader loader, Path testRoot, Map<String, String> properties) {
        // the session loads the engines from the test's own class path, before the switch of the context loader
        org.junit.platform.launcher.LauncherSession session = LauncherFactory.openSession();
        Launcher launcher = session.getLauncher();
        List<Outcome> outcomes = new ArrayList<>();
        TestExecutionListener listener = new TestExecutionListener() {
            @Override
            public void executionFinished(TestIdentifier id, TestExecutionResult result) {
                if (!id.isTest()) {
                    return;
                }
                outcomes.add(outcome(id, result.getStatus(), result.getThrowable()));
            }

            @Override
            public void executionSkipped(TestIdentifier id, String reason) {
                if (id.isTest()) {
                    outcomes.add(new Outcome(className(id), id.getDisplayName(), TestExecutionResult.Status.ABORTED, reason, null));
                }
            }
        };
        Thread t = Thread.currentThread();
        ClassLoader saved = t.getContextClassLoader();
        Map<String, String> savedProperties = new java.util.HashMap<>();
        properties.forEach((k, v) -> savedProperties.put(k, System.setProperty(k, v)));
        try {
            t.setContextClassLoader(loader);
            LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request()
                    .selectors(selectClasspathRoots(Set.of(testRoot.toAbsolutePath())))
                    .configurationParameter("junit.jupiter.testclass.order.default", "org.junit.jupiter.api.ClassOrderer$OrderAnnotation")
                    .build();
            launcher.execute(request, listener);
        } finally {
            session.close();
            t.setContextClassLoader(saved);
            savedProperties.forEach((k, v) -> {
                if (v == null) {
                    System.clearProperty(k);
                } else {
                    System.setProperty(k, v);
                }
            });
        }
        return outcomes;
    }

    private static Outcome outcome(TestIdentifier id, TestExecutionResult.Status status, Optional<Throwable> failure) {
        Throwable f = failure.orElse(null);
        return new Outcome(className(id), id.getDisplayName(), status, f == null ? null : String.valueOf(f.getMessage()), f);
    }

    private static String className(TestIdentifier id) {
        return id.getSource().map(s -> s instanceof MethodSource m ? m.getClassName() : s instanceof ClassSource c ? c.getClassName() : "?")
                .orElse("?");
    }

    /** Compiles every .java file under {@code sources} into {@code out} against vecmath and JUnit's API; javac's messages, or "". */
    static String compile(Path out, Path... sources) throws IOException {
        return compileWith("", out, sources);
    }

    /** As {@link #compile}, with {@code classpath} (class folders) before the jars; sources may be single files. */
    static String compileWith(String classpath, Path out, Path... sources) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("--release", "17", "-nowarn", "-encoding", "UTF-8", "-d", out.toString(),
                "-classpath", (classpath.isEmpty() ? "" : classpath + java.io.File.pathSeparator) + jars()));
        for (Path s : sources) {
            try (Stream<Path> files = Files.walk(s)) {
                files.filter(p -> p.toString().endsWith(".java")).map(Path::toString).sorted().forEach(args::add);
            }
        }
        java.io.ByteArrayOutputStream messages = new java.io.ByteArrayOutputStream();
        int status = javac.run(null, messages, messages, args.toArray(new String[0]));
        return status == 0 ? "" : messages.toString(java.nio.charset.StandardCharsets.UTF_8);
    }

    /** The jars the course's classes compile against: vecmath, JUnit's API and params, opentest4j, apiguardian. */
    static String jars() {
        return Stream.of(javax.vecmath.Vector3d.class, org.junit.jupiter.api.Test.class, org.junit.jupiter.params.ParameterizedTest.class,
                        org.opentest4j.AssertionFailedError.class, org.apiguardian.api.API.class)
                .map(c -> {
                    try {
                        return Paths.get(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
                    } catch (java.net.URISyntaxException e) {
                        throw new IllegalStateException(e);
                    }
                })
                .distinct().collect(Collectors.joining(java.io.File.pathSeparator));
    }

    static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
