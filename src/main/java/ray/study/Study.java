package ray.study;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import ray.Failures;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;

/**
 * {@code raytracer --study scenes/*.txt}: for each scene, renders a converged reference and then every
 * sampler at every setting ({@link StudySettings}), times them, measures their error, and writes
 * {@code <scene>.csv}, plots and an {@code index.html} tying them together into the output folder
 * (default {@code build/reports/accuracy}).
 */
public final class Study {

    private final StudyRenderer renderer;
    private final StudySettings settings;
    private final int repeats;
    private final PrintStream out;
    private final PrintStream err;
    private final boolean progress;
    private int maxPixels = StudySettings.MAX_PIXELS;
    /** The terminal's width in columns, asked at each redraw of the progress line (it may be resized). */
    private java.util.function.IntSupplier columns = () -> 80;
    /** Told the scene being read or studied (its name as shown), and null after the last: the command line's exit guard. */
    private java.util.function.Consumer<String> working = name -> { };
    /** Where the scene {@code -} is read from. */
    private java.io.InputStream in = System.in;

    public Study(StudyRenderer renderer, StudySettings settings, int repeats, PrintStream out, PrintStream err, boolean progress) {
        if (repeats < 1) {
            throw new IllegalArgumentException("repeats must be at least 1");
        }
        this.renderer = renderer;
        this.settings = settings;
        this.repeats = repeats;
        this.out = out;
        this.err = err;
        this.progress = progress;
    }

    /**
     * The study as the command line runs it: the built-in renderer on {@code threads} threads, 3 repeats,
     * each scene at most {@link StudySettings#MAX_PIXELS} pixels unless {@code fullSize}; {@code columns}
     * is the terminal's width, which the progress line never exceeds.
     */
    public static int run(List<Path> scenes, boolean quick, boolean fullSize, Path outDir, int threads, java.io.InputStream in,
                          PrintStream out, PrintStream err, boolean progress, java.util.function.IntSupplier columns,
                          java.util.function.Consumer<String> working) {
        Study s = new Study(new RendererAdapter(threads), quick ? StudySettings.QUICK : StudySettings.FULL, 3, out, err, progress);
        s.in = in;
        s.columns = columns;
        s.working = working;
        if (fullSize) {
            s.maxPixels(Integer.MAX_VALUE);
        }
        return s.run(scenes, outDir, (quick ? "quick settings" : "full settings")
                + (fullSize ? ", every scene at its own size" : ", scenes over " + StudySettings.MAX_PIXELS + " pixels scaled down to that many"));
    }

    /** The built-in renderer the command line's study uses, on {@code threads} threads. */
    public static StudyRenderer localRenderer(int threads) {
        return new RendererAdapter(threads);
    }

    /** Where the scene {@code -} is read from (default: standard input). */
    public Study in(java.io.InputStream stream) {
        this.in = stream;
        return this;
    }

    /** The terminal's width for the progress line (80 unless told), asked at each redraw. */
    public Study columns(java.util.function.IntSupplier c) {
        this.columns = c;
        return this;
    }

    /** Renders scenes with more pixels than {@code n} at n pixels (same camera and aspect ratio). */
    public Study maxPixels(int n) {
        if (n < 1) {
            throw new IllegalArgumentException("maxPixels must be at least 1");
        }
        maxPixels = n;
        return this;
    }

    /**
     * Returns 0 when every scene was studied, 1 when any could not be read, rendered or reported. A
     * failing scene (a user's class throwing anything, even an Error or an exception whose message
     * throws) is one line naming it; the other scenes are still studied and the report still written.
     * The report folder is checked before the first render ({@link ReportFolder}): nothing in it that a
     * study did not write is replaced, and no link in it is followed.
     */
    public int run(List<Path> scenePaths, Path outDir, String mode) {
        long t0 = System.nanoTime();
        ReportFolder folder;
        try {
            folder = ReportFolder.open(outDir);
        } catch (IOException e) {
            err.println(Failures.oneLine(outDir + ": " + e.getMessage()));
            return 1;
        }
        List<String> names = new ArrayList<>();
        List<Scene> scenes = new ArrayList<>();
        List<int[]> sizes = new ArrayList<>();
        List<Path> parsed = new ArrayList<>();
        int failed = 0;
        for (Path p : scenePaths) {
            boolean stdin = p.toString().equals("-");
            String shown = Failures.oneLine(stdin ? "<stdin>" : p.toString());
            working.accept(shown);
            try {
                Scene scene = stdin ? Parser.parse(in, shown, new ArrayList<>()) : Parser.parse(p);
                sizes.add(new int[] {scene.width, scene.height});
                StudySettings.fit(scene, maxPixels);
                scenes.add(scene);
                parsed.add(p);
            } catch (SceneFormatException e) {
                err.println(Failures.oneLine(e.getMessage()));
                failed++;
            } catch (OutOfMemoryError e) {
                err.println(shown + ": out of memory while reading the scene (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
                failed++;
            } catch (Throwable e) {     // a user's class (static initialiser, constructor, setter)
                err.println(shown + ": reading the scene failed: " + Failures.describe(e));
                failed++;
            }
        }
        working.accept(null);
        names.addAll(ReportFolder.stems(parsed));
        List<String> files = new ArrayList<>(List.of("index.html", "adaptive-honesty.png"));
        for (String n : names) {
            files.addAll(List.of(n + ".csv", n + "-error-vs-time.png", n + "-crops.png"));
        }
        try {
            folder.claim(files);
        } catch (IOException e) {
            err.println(Failures.oneLine(e.getMessage()));
            return 1;
        }
        SceneStudy study = new SceneStudy(renderer, settings, repeats);
        double total = 0;
        for (Scene s : scenes) {
            total += study.work(s);
        }
        Bar bar = new Bar(total);
        List<SceneStudy.Outcome> outcomes = new ArrayList<>();
        for (int i = 0; i < scenes.size(); i++) {
            String name = names.get(i);
            String shown = Failures.oneLine(parsed.get(i).toString().equals("-") ? "<stdin>" : parsed.get(i).toString());
            bar.label = name;
            SceneStudy.Outcome o;
            working.accept(shown);
            try {
                renderer.studying(parsed.get(i), scenes.get(i));
                o = study.run(name, scenes.get(i), sizes.get(i)[0], sizes.get(i)[1], bar);
            } catch (OutOfMemoryError e) {
                bar.clear();
                err.println(shown + ": out of memory while rendering (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
                failed++;
                continue;
            } catch (Throwable e) {      // a user's class failing while it renders, whatever it throws
                bar.clear();
                err.println(shown + ": rendering failed: " + Failures.describe(e));
                failed++;
                continue;
            }
            outcomes.add(o);
            try {
                Report.csv(o, folder, name + ".csv");
                Plots.errorVersusTime(o, folder, name + "-error-vs-time.png");
                Plots.crops(o, folder, name + "-crops.png");
            } catch (IOException e) {
                bar.clear();
                err.println(Failures.oneLine(e.getMessage()));
                failed++;
            } catch (RuntimeException e) {   // the plotting library refusing the data
                bar.clear();
                err.println(shown + ": cannot plot the report: " + Failures.describe(e));
                failed++;
            }
        }
        working.accept(null);
        bar.clear();
        boolean honesty = false;
        try {
            honesty = Plots.honesty(outcomes, folder, "adaptive-honesty.png");
        } catch (IOException e) {
            err.println(Failures.oneLine(e.getMessage()));
            failed++;
        } catch (RuntimeException e) {
            err.println(Failures.oneLine(outDir + ": cannot plot adaptive-honesty.png: " + Failures.describe(e)));
            failed++;
        }
        try {
            Report.html(outcomes, honesty, mode, (System.nanoTime() - t0) / 1e9, repeats, folder, "index.html");
        } catch (IOException e) {
            err.println(Failures.oneLine(e.getMessage()));
            return 1;
        }
        for (SceneStudy.Outcome o : outcomes) {
            out.println(Failures.oneLine(o.name() + ": " + Report.psnrSentence(o, Report.TARGET_PSNR_DB)));
        }
        String rec = Report.recommendation(outcomes);
        if (rec != null && outcomes.size() > 1) {
            out.println(Failures.oneLine(rec));
        }
        out.println(Failures.oneLine(String.format(Locale.ROOT, "study of %d scene(s) in %.1f s: %s", outcomes.size(),
                (System.nanoTime() - t0) / 1e9, outDir.resolve("index.html"))));
        return failed == 0 ? 0 : 1;
    }

    /** A progress bar on stderr by work (samples x pixels), with the time left; drawn only on a terminal. */
    private final class Bar implements SceneStudy.Tick {
        private double total;
        private final long start = System.nanoTime();
        private double done;
        private long lastDraw;
        private int width;
        String label = "";

        Bar(double total) {
            this.total = Math.max(1, total);
        }

        @Override
        public void added(double work) {
            total += work;
        }

        @Override
        public void rendered(double work) {
            done += work;
            long now = System.nanoTime();
            if (!progress || now - lastDraw < 200_000_000L) {
                return;
            }
            lastDraw = now;
            double f = Math.min(1, done / total), elapsed = (now - start) / 1e9;
            int filled = (int) Math.round(30 * f);
            String s = String.format(Locale.ROOT, "study [%s%s] %3.0f%%  %s  %s left", "#".repeat(filled), ".".repeat(30 - filled),
                    100 * f, label, f > 0.02 ? Report.seconds(elapsed / f - elapsed) + " s" : "?");
            int columns = Math.max(1, Study.this.columns.getAsInt() - 1);    // never wrap: a wrapped line cannot be erased
            if (s.length() > columns) {
                s = s.substring(0, columns);
            }
            width = Math.min(columns, Math.max(width, s.length()));
            err.print("\r" + s + " ".repeat(Math.max(0, width - s.length())));
            err.flush();
        }

        void clear() {
            if (width > 0) {
                err.print("\r" + " ".repeat(width) + "\r");
                err.flush();
                width = 0;
            }
        }
    }
}
