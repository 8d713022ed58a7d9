package ray.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code raytracer grade -o DIR [--tests DIR] SUBMISSION...}: grades each submission (a folder or a zip
 * of .java files) and writes DIR/grades.csv, DIR/index.html and per submission DIR/NAME/results.json and
 * DIR/NAME/index.html.
 */
@Command(name = "grade", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Grades course submissions: each a folder or .zip of .java files (all framework files or only the changed ones).",
                "Each is compiled and run in its own sandboxed child JVM; its images are judged against the test set's references.",
                "Writes DIR/grades.csv, DIR/index.html, and DIR/<submission>/results.json (Gradescope) and index.html."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every submission was graded", "1:a submission could not be read (the others are graded)",
                "2:bad command line or test set"})
public final class GradeCommand implements Callable<Integer> {

    @Option(names = {"-o", "--output"}, paramLabel = "DIR", description = "where the reports go (created)")
    Path output;

    @Option(names = "--gradescope", paramLabel = "ROOT", description = "Gradescope's autograder: grade the one submission in "
            + "ROOT/submission and write ROOT/results/results.json (run_autograder passes /autograder)")
    Path gradescope;

    @Option(names = {"-j", "--jobs"}, paramLabel = "N", description = "submissions graded at once (default: the number of cores, ${DEFAULT-VALUE})")
    int jobs = Runtime.getRuntime().availableProcessors();

    /** --tests, --sandbox, --work. */
    @Mixin
    GradeOptions grading = new GradeOptions();

    @Parameters(paramLabel = "SUBMISSION", arity = "0..*", description = "folders or .zip files, one per student")
    List<Path> submissions = new ArrayList<>();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintStream out = new PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out), true, StandardCharsets.UTF_8);
        PrintStream err = System.err;
        if (spec != null) {
            out = toStream(spec.commandLine().getOut());
            err = toStream(spec.commandLine().getErr());
        }
        return run(out, err);
    }

    private static PrintStream toStream(java.io.PrintWriter w) {
        return new PrintStream(new java.io.OutputStream() {
            @Override
            public void write(int b) {
                w.write(b);
            }

            @Override
            public void write(byte[] b, int off, int len) {
                w.write(new String(b, off, len, StandardCharsets.UTF_8));
            }

            @Override
            public void flush() {
                w.flush();
            }
        }, true, StandardCharsets.UTF_8);
    }

    int run(PrintStream out, PrintStream err) {
        if (jobs < 1) {
            err.println("raytracer grade: --jobs must be at least 1");
            return 2;
        }
        if (gradescope != null ? output != null || !submissions.isEmpty() : output == null || submissions.isEmpty()) {
            err.println("raytracer grade: give -o DIR and submissions, or --gradescope ROOT alone (see raytracer grade --help)");
            return 2;
        }
        TestSet set;
        Sandbox box;
        try {
            set = grading.testSet();
            box = Sandbox.choose(grading.sandbox);
            if (gradescope != null) {
                return gradescope(set, box, out, err);
            }
            Files.createDirectories(output);
        } catch (IOException e) {
            err.println("raytracer grade: " + e.getMessage());
            return 2;
        }
        if (box.kind() == Sandbox.Kind.NONE) {
            err.println("raytracer grade: warning: " + box.description());
        }
        try {
            Path scratch = GradeOptions.scratch(grading.work);
            Grader grader = new Grader(set, box, Judge.standard(), Files.createTempDirectory(scratch, "raytracer-grade-"));
            try {
                return gradeAll(grader, out, err);
            } finally {
                grader.close();
                Grader.deleteTree(grader.work());
            }
        } catch (IOException e) {
            err.println("raytracer grade: " + e.getMessage());
            return 1;
        }
    }

    /** One submission, Gradescope's way: ROOT/submission in, ROOT/results/results.json out (its report beside it). */
    private int gradescope(TestSet set, Sandbox box, PrintStream out, PrintStream err) throws IOException {
        Path results = Files.createDirectories(gradescope.resolve("results"));
        Path scratch = GradeOptions.scratch(grading.work);
        Grader grader = new Grader(set, box, Judge.standard(), Files.createTempDirectory(scratch, "raytracer-grade-"));
        try {
            Submission s = Submission.read(gradescope.resolve("submission"));
            SubmissionResult r = grader.grade(s, results.resolve("report"));
            Files.writeString(results.resolve("report/index.html"), Reports.studentHtml(r), StandardCharsets.UTF_8);
            Files.writeString(results.resolve("results.json"), Reports.resultsJson(r), StandardCharsets.UTF_8);
            out.println(s.name() + ": " + Reports.num(r.score()) + " / " + Reports.num(r.maxScore()));
            return 0;
        } finally {
            grader.close();
            Grader.deleteTree(grader.work());
        }
    }

    private int gradeAll(Grader grader, PrintStream out, PrintStream err) throws IOException {
        long t0 = System.nanoTime();
        List<String> problems = new ArrayList<>();
        List<Submission> subs = Submission.readAll(submissions, problems);
        problems.forEach(p -> err.println("raytracer grade: " + p));
        int unreadable = problems.size();
        int n = Math.min(jobs, Math.max(1, subs.size()));
        ExecutorService pool = Executors.newFixedThreadPool(n);
        List<Future<SubmissionResult>> futures = new ArrayList<>();
        for (Submission s : subs) {
            futures.add(pool.submit(() -> {
                SubmissionResult r = grader.grade(s, output.resolve(s.name()));
                Reports.writeSubmission(r, output.resolve(s.name()));
                return r;
            }));
        }
        pool.shutdown();
        List<SubmissionResult> results = new ArrayList<>();
        for (int i = 0; i < futures.size(); i++) {
            try {
                SubmissionResult r = futures.get(i).get();
                results.add(r);
                out.println(Reports.scoreLine(r));
            } catch (java.util.concurrent.ExecutionException e) {
                Throwable c = e.getCause();
                err.println("raytracer grade: " + subs.get(i).name() + ": the grader failed: " + c);
                unreadable++;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return 1;
            }
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        out.println(Reports.writeClass(output, results, grader.testSet(), grader.sandbox().description(), wall, n));
        return unreadable == 0 ? 0 : 1;
    }

    /**
     * The course kit's test set: {@code -Draytracer.course=KIT} (then KIT/grading), else
     * {@code <app home>/course/grading} of the installed launcher, else {@code build/course-kit/grading}
     * (a build from the project's folder).
     */
    public static Path defaultTests() throws IOException {
        String prop = System.getProperty("raytracer.course");
        if (prop != null) {
            return Path.of(prop).resolve("grading");
        }
        try {
            Path jar = Path.of(GradeCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            Path home = jar.getParent() == null ? null : jar.getParent().getParent();
            if (jar.toString().endsWith(".jar") && home != null && Files.isDirectory(home.resolve("course/grading"))) {
                return home.resolve("course/grading");
            }
        } catch (java.net.URISyntaxException | RuntimeException e) {
            // fall through
        }
        Path dev = Path.of("build", "course-kit", "grading");
        if (Files.isDirectory(dev)) {
            return dev;
        }
        throw new IOException("no test set: give --tests DIR (a folder with rubric.txt), or install the course kit "
                + "(gradle installDist puts it in <app home>/course)");
    }
}
