package ray.study;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import ray.render.RenderSummary;

/** Writes a scene's CSV and the study's index.html, and words the findings as sentences. */
final class Report {

    /** The PSNR the headline sentence asks for. */
    static final double TARGET_PSNR_DB = 40;

    private Report() {
    }

    static void csv(SceneStudy.Outcome o, ReportFolder dir, String file) throws IOException {
        StringBuilder b = new StringBuilder(Row.HEADER).append('\n');
        for (Row r : o.rows()) {
            b.append(r.csv()).append('\n');
        }
        dir.write(file, b.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** The sampler rows (not the MaxDepth ones), by sampler, in study order. */
    static Map<String, List<Row>> bySampler(SceneStudy.Outcome o) {
        Map<String, List<Row>> m = new LinkedHashMap<>();
        for (Row r : o.rows()) {
            if (!Plots.isDepthRow(r, o)) {
                m.computeIfAbsent(r.setting().sampler(), k -> new ArrayList<>()).add(r);
            }
        }
        return m;
    }

    /**
     * The cheapest row of {@code rows} with an RMSE at most {@code rmse}, or null. Times are noisy, so a
     * row is only faster than another when the middle halves of their times over the repeats
     * ({@link Row#costLow()} to {@link Row#costHigh()}) do not overlap: among the rows whose middle half
     * overlaps the fastest one's, the one with the fewest samples per pixel wins (a tie goes to the
     * cheaper setting), then the lower median.
     */
    static Row cheapest(List<Row> rows, double rmse) {
        Row fastest = null;
        for (Row r : rows) {
            if (r.error().rmse <= rmse && (fastest == null || r.cost() < fastest.cost())) {
                fastest = r;
            }
        }
        if (fastest == null) {
            return null;
        }
        Row best = fastest;
        for (Row r : rows) {
            if (r.error().rmse <= rmse && r.costLow() <= fastest.costHigh()
                    && (r.meanSpp() < best.meanSpp() || r.meanSpp() == best.meanSpp() && r.cost() < best.cost())) {
                best = r;
            }
        }
        return best;
    }

    /** The machines the study's renders ran on, in order of first use ({@code ""}: this process). */
    static List<String> machines(List<SceneStudy.Outcome> outcomes) {
        List<String> out = new ArrayList<>();
        for (SceneStudy.Outcome o : outcomes) {
            for (String m : o.machines()) {
                if (!out.contains(m)) {
                    out.add(m);
                }
            }
        }
        return out;
    }

    /** {@code 2.1 s CPU (1.1 s wall)}, or the wall time alone where no CPU time was measured. */
    static String time(Row r) {
        return Double.isNaN(r.cpuMedian()) ? seconds(r.secondsMedian()) + " s"
                : seconds(r.cpuMedian()) + " s CPU, " + seconds(r.secondsMedian()) + " s wall";
    }

    /**
     * Over all scenes: the sampler setting that reaches {@link #TARGET_PSNR_DB} in the most scenes, and
     * among those (within the timing noise of one another's total) the cheapest in samples; with the
     * grid setting that does as well, for comparison. Null with fewer than one scene.
     */
    static String recommendation(List<SceneStudy.Outcome> outcomes) {
        double rmse = Math.pow(10, -TARGET_PSNR_DB / 20);
        Map<String, double[]> tally = new LinkedHashMap<>();      // key -> reached, total cost, total spp, total cost range width
        for (SceneStudy.Outcome o : outcomes) {
            for (Map.Entry<String, List<Row>> e : bySampler(o).entrySet()) {
                for (Row r : e.getValue()) {
                    double[] t = tally.computeIfAbsent(e.getKey() + " " + r.setting().label(), k -> new double[4]);
                    t[0] += r.error().rmse <= rmse ? 1 : 0;
                    t[1] += r.cost();
                    t[2] += r.meanSpp();
                    t[3] += r.costHigh() - r.costLow();
                }
            }
        }
        if (tally.isEmpty()) {
            return null;
        }
        double most = tally.values().stream().mapToDouble(t -> t[0]).max().orElse(0);
        if (most == 0) {
            return String.format(Locale.ROOT, "No setting studied reaches PSNR %.0f dB in any of these scenes, so there is no "
                    + "setting to recommend for it (the tables give each setting's error).", TARGET_PSNR_DB);
        }
        String best = null, bestGrid = null;
        for (Map.Entry<String, double[]> e : tally.entrySet()) {
            double[] t = e.getValue();
            if (t[0] < most) {
                continue;
            }
            if (best == null || better(t, tally.get(best))) {
                best = e.getKey();
            }
            if (e.getKey().startsWith("grid ") && (bestGrid == null || better(t, tally.get(bestGrid)))) {
                bestGrid = e.getKey();
            }
        }
        double[] b = tally.get(best);
        String s = String.format(Locale.ROOT, "For scenes like these, use %s: it reaches PSNR %.0f dB in %d of %d scenes (no setting "
                + "studied does in more) for %s s of CPU time over all of them.", best.replace(" ", " with "), TARGET_PSNR_DB, (int) b[0],
                outcomes.size(), seconds(b[1]));
        if (bestGrid != null && !bestGrid.equals(best)) {
            double[] g = tally.get(bestGrid);
            s += String.format(Locale.ROOT, " The cheapest grid setting that does as well, %s, takes %s s (%.2fx).", bestGrid.replace(" ", " with "),
                    seconds(g[1]), g[1] / b[1]);
        }
        return s;
    }

    /** Cheaper over all scenes: a lower total cost beyond the two totals' noise, else fewer samples. */
    private static boolean better(double[] a, double[] b) {
        double noise = a[3] + b[3];
        if (Math.abs(a[1] - b[1]) > noise) {
            return a[1] < b[1];
        }
        return a[2] < b[2] || a[2] == b[2] && a[1] < b[1];
    }

    /** "to reach PSNR 40 dB: grid needs n_s=5 (2.1 s); adaptive needs 0.6 s (target=1)". */
    static String psnrSentence(SceneStudy.Outcome o, double psnrDb) {
        double rmse = Math.pow(10, -psnrDb / 20);
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, List<Row>> e : bySampler(o).entrySet()) {
            Row r = cheapest(e.getValue(), rmse);
            if (r == null) {
                parts.add(e.getKey() + " does not reach it in the settings studied");
            } else {
                parts.add(e.getKey() + " needs " + r.setting().label() + " (" + time(r) + ")");
            }
        }
        return String.format(Locale.ROOT, "To reach PSNR %.0f dB: ", psnrDb) + String.join("; ", parts) + ".";
    }

    /** How fast adaptive matches grid n_s = 4's RMSE, or null without both. */
    static String adaptiveSentence(SceneStudy.Outcome o) {
        Map<String, List<Row>> m = bySampler(o);
        Row grid4 = find(m.get("grid"), "n_s=4");
        if (grid4 == null || !m.containsKey("adaptive")) {
            return null;
        }
        // 1% over counts as reaching it: adaptive with the n_s = 4 budget converges to that very image
        Row a = cheapest(m.get("adaptive"), grid4.error().rmse * 1.01);
        if (a == null) {
            return String.format(Locale.ROOT, "Adaptive does not reach the 4x4 grid's RMSE (%.2f steps) at the targets studied.", grid4.rmseSteps());
        }
        return String.format(Locale.ROOT, "Adaptive reaches the 4x4 grid's RMSE (%.2f steps) with %s in %s: %.2fx the grid's time (%s), "
                + "with %.1f samples per pixel on average.", grid4.rmseSteps(), a.setting().label(), time(a), a.cost() / grid4.cost(), time(grid4),
                a.meanSpp());
    }

    /** Which sampler has the lowest RMSE at n_s = {@code ns} (equal samples per pixel). */
    static String equalSamplesSentence(SceneStudy.Outcome o, int ns) {
        List<String> parts = new ArrayList<>();
        String best = null;
        double bestRmse = Double.POSITIVE_INFINITY;
        for (Map.Entry<String, List<Row>> e : bySampler(o).entrySet()) {
            Row r = find(e.getValue(), "n_s=" + ns);
            if (r != null) {
                parts.add(String.format(Locale.ROOT, "%s %.2f", e.getKey(), r.rmseSteps()));
                if (r.error().rmse < bestRmse) {
                    bestRmse = r.error().rmse;
                    best = e.getKey();
                }
            }
        }
        if (parts.size() < 2) {
            return null;
        }
        return String.format(Locale.ROOT, "At %d samples per pixel the RMSE (8-bit steps) is %s: %s wins.", ns * ns, String.join(", ", parts), best);
    }

    /**
     * The adaptive estimate's ratio to the true RMSE of row {@code r} (the reference's own noise taken
     * out, {@link Reference#trueSteps}), both raised to the estimate's resolution
     * ({@link RenderSummary#ESTIMATE_RESOLUTION}: below it, "under 0.05 steps" is all either says), or
     * NaN without an estimate.
     */
    static double honesty(SceneStudy.Outcome o, Row r) {
        double res = RenderSummary.ESTIMATE_RESOLUTION, truth = o.ref().trueSteps(r.rmseSteps());
        return Double.isNaN(r.estimatedRmseSteps()) ? Double.NaN : Math.max(res, r.estimatedRmseSteps()) / Math.max(res, truth);
    }

    /** The range of the adaptive estimate's ratio to the true RMSE, or null. */
    static double[] honestyRange(SceneStudy.Outcome o) {
        double lo = Double.POSITIVE_INFINITY, hi = 0;
        for (Row r : o.rows()) {
            double q = honesty(o, r);
            if (!Double.isNaN(q)) {
                lo = Math.min(lo, q);
                hi = Math.max(hi, q);
            }
        }
        return hi == 0 ? null : new double[] {lo, hi};
    }

    /** One sentence on the adaptive estimate over all scenes: ratios, how many within 1.5, interval coverage. */
    static String honestySummary(List<SceneStudy.Outcome> outcomes) {
        List<Double> ratios = new ArrayList<>();
        int within = 0, covered = 0, below = 0;
        double cost = 0;
        for (SceneStudy.Outcome o : outcomes) {
            for (Row r : o.rows()) {
                double q = honesty(o, r);
                if (Double.isNaN(q)) {
                    continue;
                }
                ratios.add(q);
                within += q >= 1 / 1.5 && q <= 1.5 ? 1 : 0;
                double truth = o.ref().trueSteps(r.rmseSteps());
                covered += truth >= r.estimate().lowSteps() && truth <= r.estimate().highSteps() ? 1 : 0;
                below += truth < RenderSummary.ESTIMATE_RESOLUTION ? 1 : 0;
                cost += r.estimate().samplesPerPixel();
            }
        }
        if (ratios.isEmpty()) {
            return "";
        }
        java.util.Collections.sort(ratios);
        int n = ratios.size();
        return String.format(Locale.ROOT, "%d adaptive renders: estimate / true RMSE from %.2f to %.2f (median %.2f), %d of them within a "
                + "factor of 1.5; the 95%% interval held the truth in %d; %d had a true error below the estimate's resolution of %s steps; "
                + "the estimate cost %.1f samples per pixel on average.", n, ratios.get(0), ratios.get(n - 1), ratios.get(n / 2), within,
                covered, below, RenderSummary.ESTIMATE_RESOLUTION, cost / n);
    }

    /** "sobol, two halves of n_s = 16 (512 samples per pixel); noise 0.02 steps; 0.05 steps from the level before". */
    static String referenceSentence(SceneStudy.Outcome o) {
        Reference r = o.ref();
        String s = String.format(Locale.ROOT, "%s sampler, mean of two independent renders of n_s = %d (%d samples per pixel in all)",
                r.sampler(), r.ns(), r.spp());
        s += String.format(Locale.ROOT, "; its own error (half the RMS difference of the two) is %.3f steps", r.noiseSteps());
        if (r.change() != null) {
            s += String.format(Locale.ROOT, "; it moved %.3f steps RMS from the level before (n_s = %d, a quarter of the samples)",
                    r.change().rmse / ImageError.STEP, r.ns() / 2);
        } else {
            s += " (its first level was enough: noise at most a third of the smallest error judged)";
        }
        return s;
    }

    static Row find(List<Row> rows, String label) {
        if (rows != null) {
            for (Row r : rows) {
                if (r.setting().label().equals(label)) {
                    return r;
                }
            }
        }
        return null;
    }

    static String seconds(double s) {
        if (Double.isNaN(s)) {
            return "-";
        }
        return s >= 10 ? String.format(Locale.ROOT, "%.1f", s) : s >= 0.1 ? String.format(Locale.ROOT, "%.2f", s)
                : String.format(Locale.ROOT, "%.3f", s);
    }

    static void html(List<SceneStudy.Outcome> outcomes, boolean honesty, String mode, double totalSeconds, int repeats, ReportFolder dir, String file) throws IOException {
        StringBuilder b = new StringBuilder();
        b.append("<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Accuracy against time</title>\n")
                .append("<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em}")
                .append(".wide{overflow-x:auto;max-width:100%}.wide td{white-space:nowrap}.text td{text-align:left;vertical-align:top}")
                .append("table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}")
                .append("th{background:#f4f4f4}td:first-child,td:nth-child(2){text-align:left}img{max-width:100%}")
                .append("h2{margin-top:2em;border-top:1px solid #ddd;padding-top:1em}</style></head><body>\n")
                .append("<h1>What accuracy costs in time</h1>\n<p>Each scene was rendered with every sampler at every setting (")
                .append(esc(mode)).append("), timed after a warm-up render, and compared with a converged reference on the clamped ")
                .append("linear image. Each render's CPU time is read from the clocks of the threads that rendered it (other work on the ")
                .append("machine, or in the same JVM, does not count), its wall time beside it. Every setting is rendered ").append(repeats)
                .append(" times; a setting whose CPU times still spread widely (the middle half of them wider than a tenth of their ")
                .append("median, or 3 ms) is rendered again, ").append(repeats).append(" more at a time, up to ").append(SceneStudy.MAX_REPEATS)
                .append(" times as often; the tables give the repeats, the median and the middle half (quartiles). Settings are judged ")
                .append("by CPU time: one counts as faster than another only when their middle halves do not overlap, and a tie goes to ")
                .append("the setting with fewer samples per pixel. Errors are in 8-bit steps (1/255 of the [0, 1] range, the unit of ")
                .append("--target-error and of the PNG); the CSVs also keep the [0, 1] fractions. Study time: ")
                .append(seconds(totalSeconds)).append(" s.</p>\n");
        List<String> machines = machines(outcomes);
        if (machines.size() > 1) {
            b.append("<p><b>Times from different machines.</b> The renders ran on ").append(machines.size()).append(" machines (")
                    .append(esc(String.join(", ", machines))).append("); each time was measured inside its render on the machine that ")
                    .append("ran it, so a setting's repeats may come from different machines, and settings compare only as far as those ")
                    .append("machines are alike.</p>\n");
        }
        b.append("<p><b>Why 40 dB.</b> The report asks what each sampler needs to reach PSNR 40 dB: an RMSE of 1% of the range, ")
                .append(String.format(Locale.ROOT, "%.2f", Math.pow(10, -TARGET_PSNR_DB / 20) / ImageError.STEP))
                .append(" 8-bit steps. Image-quality practice reads differences above 40 dB as hard to see (lossy codecs at high quality ")
                .append("land at 40-50 dB); below it, noise shows in smooth areas. So 40 dB is a fair bar for a finished render in a ")
                .append("course or a preview; a render compared pixel by pixel with a reference (the grader, the viewer's difference) ")
                .append("needs more, and for that the report gives the 4 x 4 grid's error beside it and draws the one-step line in ")
                .append("the plots.</p>\n");
        String rec = recommendation(outcomes);
        if (rec != null) {
            b.append("<p><b>Recommendation.</b> ").append(esc(rec)).append("</p>\n");
        }
        b.append("<h2>Summary</h2>\n<table class=\"text\"><tr><th>scene</th><th>PSNR 40 dB</th><th>adaptive vs 4x4 grid</th>")
                .append("<th>estimate / true RMSE</th><th>reference n_s, noise, change (steps)</th></tr>\n");
        for (SceneStudy.Outcome o : outcomes) {
            double[] h = honestyRange(o);
            String adaptive = adaptiveSentence(o);
            b.append("<tr><td><a href=\"#").append(esc(o.name())).append("\">").append(esc(o.name())).append("</a></td><td>")
                    .append(esc(psnrSentence(o, TARGET_PSNR_DB))).append("</td><td>").append(adaptive == null ? "" : esc(adaptive))
                    .append("</td><td>").append(h == null ? "" : String.format(Locale.ROOT, "%.2f to %.2f", h[0], h[1]))
                    .append("</td><td>").append(String.format(Locale.ROOT, "2x%d, %.3f, %s", o.ref().ns(), o.ref().noiseSteps(),
                            o.ref().change() == null ? "-" : String.format(Locale.ROOT, "%.3f", o.ref().change().rmse / ImageError.STEP)))
                    .append("</td></tr>\n");
        }
        b.append("</table>\n");
        if (honesty) {
            b.append("<h2>Does the adaptive sampler know its own error?</h2>\n<p>Each point is one adaptive render: the RMSE it ")
                    .append("reported against the RMSE it really has (the reference's noise taken out). Points between the dashed lines ")
                    .append("are within a factor of 1.5. ").append(esc(honestySummary(outcomes))).append("</p>\n")
                    .append("<img src=\"adaptive-honesty.png\" alt=\"adaptive estimate against true error\">\n");
        }
        for (SceneStudy.Outcome o : outcomes) {
            String n = esc(o.name());
            b.append("<h2 id=\"").append(n).append("\">").append(n).append("</h2>\n<p>").append(esc(psnrSentence(o, TARGET_PSNR_DB)));
            String a = adaptiveSentence(o);
            if (a != null) {
                b.append(' ').append(esc(a));
            }
            String eq = equalSamplesSentence(o, 4);
            if (eq != null) {
                b.append(' ').append(esc(eq));
            }
            b.append("</p>\n<p>Rendered at ").append(o.scene().width).append(" x ").append(o.scene().height);
            if (o.scene().width != o.fullWidth() || o.scene().height != o.fullHeight()) {
                b.append(" (the scene's own size is ").append(o.fullWidth()).append(" x ").append(o.fullHeight()).append(")");
            }
            b.append(". Reference: ").append(esc(referenceSentence(o))).append(".</p>\n");
            honestyTable(b, o);
            b.append("")
                    .append("<img src=\"").append(n).append("-error-vs-time.png\" alt=\"error against time\">\n")
                    .append("<p>The region where the 1-sample grid errs most, at each grid setting and in the reference:</p>\n")
                    .append("<img src=\"").append(n).append("-crops.png\" alt=\"worst region\">\n")
                    .append("<p><a href=\"").append(n).append(".csv\">").append(n).append(".csv</a> (every column); here in 8-bit steps:</p>\n")
                    .append("<div class=\"wide\"><table><tr><th>sampler</th><th>setting</th><th>spp</th><th>CPU s</th>")
                    .append("<th>CPU middle half</th><th>wall s</th><th>wall range</th><th>repeats</th><th>RMSE</th><th>PSNR dB</th>")
                    .append("<th>max error</th><th>pixels off &gt; 1 step</th><th>estimate</th></tr>\n");
            for (Row r : o.rows()) {
                b.append(String.format(Locale.ROOT, "<tr><td>%s</td><td>%s</td><td>%.1f</td><td>%s</td><td>%s&ndash;%s</td><td>%s</td>"
                        + "<td>%s&ndash;%s</td><td>%d</td><td>%.3f</td><td>%s</td><td>%.1f</td><td>%.1f%%</td><td>%s</td></tr>%n",
                        esc(r.setting().sampler()), esc(r.setting().label()), r.meanSpp(), seconds(r.cpuMedian()), seconds(r.cpuQ1()),
                        seconds(r.cpuQ3()), seconds(r.secondsMedian()), seconds(r.secondsMin()), seconds(r.secondsMax()), r.repeats(),
                        r.rmseSteps(), Double.isInfinite(r.error().psnrDb) ? "inf" : String.format(Locale.ROOT, "%.1f", r.error().psnrDb),
                        r.error().maxError / ImageError.STEP, 100 * r.error().shareOffByMoreThanOneStep,
                        Double.isNaN(r.estimatedRmseSteps()) ? "" : String.format(Locale.ROOT, "%.3f", r.estimatedRmseSteps())));
            }
            b.append("</table></div>\n");
        }
        b.append("</body></html>\n");
        dir.write(file, b.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** The adaptive rows: estimate and its interval against the truth, with the reference's noise shown. */
    private static void honestyTable(StringBuilder b, SceneStudy.Outcome o) {
        List<Row> rows = new ArrayList<>();
        for (Row r : o.rows()) {
            if (!Double.isNaN(r.estimatedRmseSteps())) {
                rows.add(r);
            }
        }
        if (rows.isEmpty()) {
            return;
        }
        b.append("<p>Adaptive's own estimate against the truth (8-bit steps; true = RMSE against the reference with its noise of ")
                .append(String.format(Locale.ROOT, "%.3f", o.ref().noiseSteps())).append(" taken out; the ratio takes both at least ")
                .append(RenderSummary.ESTIMATE_RESOLUTION).append(" steps, the estimate's resolution):</p>\n<table><tr><th>setting</th>")
                .append("<th>spp</th><th>estimate</th><th>95% interval</th><th>true</th><th>estimate / true</th><th>estimate cost (spp)</th></tr>\n");
        for (Row r : rows) {
            double truth = o.ref().trueSteps(r.rmseSteps()), res = RenderSummary.ESTIMATE_RESOLUTION;
            b.append(String.format(Locale.ROOT, "<tr><td>%s</td><td>%.1f</td><td>%.3f</td><td>%.3f to %.3f</td><td>%.3f</td><td>%.2f%s</td><td>%.2f</td></tr>%n",
                    esc(r.setting().label()), r.meanSpp(), r.estimatedRmseSteps(), r.estimate().lowSteps(), r.estimate().highSteps(),
                    truth, honesty(o, r), truth < res && r.estimatedRmseSteps() < res ? " (both below " + res + ")" : "",
                    r.estimate().samplesPerPixel()));
        }
        b.append("</table>\n");
    }

    static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
