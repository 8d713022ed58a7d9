package ray.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import org.apache.spark.SparkException;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import ray.app.RenderReport;
import ray.grade.GradeOptions;
import ray.grade.Reports;
import ray.grade.Submission;
import ray.grade.SubmissionResult;
import ray.grade.TestSet;
import scala.runtime.AbstractFunction2;
import scala.runtime.BoxedUnit;

/**
 * {@code raytracer-spark grade -o DIR [--tests DIR] SUBMISSION...}: {@code raytracer grade} (package
 * ray.grade: the same sandboxed child JVMs, judge, grades.csv and reports) with each submission graded by
 * a Spark task. The driver reads the test set and the hand-ins (its mistakes are refused before any task,
 * as raytracer grade refuses them), ships the test set once per executor and each hand-in with its task;
 * every executor grades with its own {@link ray.grade.Grader} (sandbox chosen on its host) and sends back
 * the result and the report's pictures; the driver writes each submission's report as it arrives, then
 * grades.csv and the class page.
 *
 * <p>One task per submission, not per (submission, test): the grader compiles a submission once and runs
 * all its tests in one child JVM, restarting after a crash from the next test, under one time budget for
 * the whole submission; and a scene's message names the failing checks of its methods. Per-test tasks
 * would compile each submission once per test and change those results (docs/scale-out.md).
 */
@Command(name = "grade", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"raytracer grade on an Apache Spark cluster: each submission (a folder or .zip of .java files) is a task,",
                "compiled and run in its own sandboxed child JVM on the executor that runs it; its images are judged there.",
                "Writes DIR/grades.csv, DIR/index.html and DIR/<submission>/ as raytracer grade does. Default master: local[*]."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every submission was graded", "1:a submission could not be read or graded (the others are graded)",
                "2:bad command line or test set"})
final class GradeJob implements Callable<Integer> {

    /** --master, --conf. */
    @CommandLine.Mixin
    ClusterOptions cluster = new ClusterOptions();

    @Option(names = {"-o", "--output"}, paramLabel = "DIR", description = "where the reports go (created; on the driver's file system)")
    Path output;

    /** --tests (read on the driver, shipped to the executors), --sandbox (chosen on each executor), --work (a folder on each executor). */
    @CommandLine.Mixin
    GradeOptions grading = new GradeOptions();

    @Parameters(paramLabel = "SUBMISSION", arity = "0..*", description = "folders or .zip files, one per student")
    List<Path> submissions = new ArrayList<>();

    @ParentCommand
    SparkMain parent;

    @Override
    public Integer call() {
        PrintStream out = parent != null ? parent.out : System.out, err = parent != null ? parent.err : System.err;
        String problem = output == null || submissions.isEmpty() ? "give -o DIR and submissions (see raytracer-spark grade --help)"
                : cluster.problem();
        if (problem != null) {
            err.println(RenderReport.oneLine("raytracer-spark grade: " + problem));
            return 2;
        }
        TestSet set;
        try {
            set = grading.testSet();
            Files.createDirectories(output);
        } catch (IOException e) {
            err.println(RenderReport.oneLine("raytracer-spark grade: " + e.getMessage()));
            return 2;
        }
        List<String> problems = new ArrayList<>();
        List<Submission> subs = Submission.readAll(submissions, problems);
        problems.forEach(p -> err.println(RenderReport.oneLine("raytracer-spark grade: " + p)));
        if (subs.isEmpty()) {   // as raytracer grade: an empty class report, no Spark
            try {
                out.println(Reports.writeClass(output, List.of(), set, "nothing graded", 0, 1));
            } catch (IOException e) {
                err.println(RenderReport.oneLine("raytracer-spark grade: " + e.getMessage()));
            }
            return 1;
        }
        try (JavaSparkContext jsc = new JavaSparkContext(cluster.sparkConf(1))) {
            int failed = run(jsc, set, subs, out, err, RenderReport.stderrIsTerminal());
            return problems.isEmpty() && failed == 0 ? 0 : 1;
        } catch (IOException e) {
            err.println(RenderReport.oneLine("raytracer-spark grade: " + e.getMessage()));
            return 1;
        } finally {
            GradeTasks.release();   // local mode: the executors' test sets and scratch were in this JVM
        }
    }

    /**
     * Grades {@code subs} as the tasks of one job and writes every report; returns how many submissions
     * could not be graded (each named on {@code err}).
     */
    int run(JavaSparkContext jsc, TestSet set, List<Submission> subs, PrintStream out, PrintStream err, boolean showProgress)
            throws IOException {
        long t0 = System.nanoTime();
        GradeTasks.TestSetBundle bundle = GradeTasks.TestSetBundle.of(set);
        Broadcast<GradeTasks.TestSetBundle> shipped = jsc.broadcast(bundle);
        List<GradeTasks.Hand> hands = new ArrayList<>();
        for (int i = 0; i < subs.size(); i++) {
            hands.add(new GradeTasks.Hand(i, subs.get(i)));
        }
        Progress progress = new Progress(err, showProgress, "submission");
        progress.start(hands.size(), hands.size());
        OnResult collect = new OnResult(subs, progress, out, err);
        JavaRDD<GradeTasks.Hand> rdd = jsc.parallelize(hands, hands.size());
        jsc.setJobDescription("raytracer-spark grade: " + hands.size() + " submission(s), test set of " + set.items().size() + " item(s)");
        try {
            GradeTasks.Grade grade = new GradeTasks.Grade(shipped, grading.sandbox, grading.work == null ? null : grading.work.toString());
            jsc.sc().runJob(rdd.rdd(), new EachTask<>(grade, GradeTasks.Graded.class), collect, EachTask.arrayTag(GradeTasks.Graded.class));
        } catch (Exception e) {     // SparkException, thrown undeclared by Scala code: the job failed as a whole
            Throwable cause = !(e instanceof SparkException) && e.getCause() instanceof SparkException ? e.getCause() : e;
            progress.clear();
            for (int i = 0; i < subs.size(); i++) {
                if (!collect.results.containsKey(i) && !collect.failed.contains(i)) {
                    err.println(RenderReport.oneLine("raytracer-spark grade: " + subs.get(i).name() + ": the Spark job failed: "
                            + String.valueOf(cause.getMessage()).lines().findFirst().orElse("")));
                    collect.failed.add(i);
                }
            }
        } finally {
            shipped.destroy();
            progress.clear();
        }
        List<SubmissionResult> results = new ArrayList<>(collect.results.values());
        Set<String> boxes = new LinkedHashSet<>();
        results.forEach(r -> boxes.add(r.sandbox()));
        for (String b : boxes) {
            if (!b.startsWith("bubblewrap")) {
                err.println(RenderReport.oneLine("raytracer-spark grade: warning: some executors ran student code with " + b));
            }
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        String line = Reports.writeClass(output, results, set, boxes.isEmpty() ? "nothing graded" : String.join("; ", boxes), wall,
                Math.min(subs.size(), jsc.defaultParallelism()));
        out.println(line);
        return collect.failed.size();
    }

    /** The driver side: each submission's report written as it arrives (Spark calls this from one thread). */
    private final class OnResult extends AbstractFunction2<Object, GradeTasks.Graded[], BoxedUnit> {
        final Map<Integer, SubmissionResult> results = new TreeMap<>();
        final Set<Integer> failed = new HashSet<>();
        private final List<Submission> subs;
        private final Progress progress;
        private final PrintStream out, err;

        OnResult(List<Submission> subs, Progress progress, PrintStream out, PrintStream err) {
            this.subs = subs;
            this.progress = progress;
            this.out = out;
            this.err = err;
        }

        @Override
        public BoxedUnit apply(Object partition, GradeTasks.Graded[] graded) {
            for (GradeTasks.Graded g : graded) {
                if (results.containsKey(g.index()) || failed.contains(g.index())) {
                    continue;    // a rerun copy of a task already in
                }
                progress.clear();
                if (g.failure() != null) {
                    err.println(RenderReport.oneLine("raytracer-spark grade: " + subs.get(g.index()).name() + ": " + g.failure()));
                    failed.add(g.index());
                } else {
                    try {
                        Path dir = Files.createDirectories(output.resolve(g.result().name()));
                        for (Map.Entry<String, byte[]> f : g.images().entrySet()) {
                            Files.write(dir.resolve(f.getKey()), f.getValue());
                        }
                        Reports.writeSubmission(g.result(), dir);
                        results.put(g.index(), g.result());
                        out.println(Reports.scoreLine(g.result()));
                    } catch (IOException e) {
                        err.println(RenderReport.oneLine("raytracer-spark grade: " + g.result().name() + ": cannot write its report: "
                                + e.getMessage()));
                        failed.add(g.index());
                    }
                }
            }
            progress.done(graded.length, results.size() + failed.size());
            return BoxedUnit.UNIT;
        }
    }
}
