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

    /** The fastest row (median time) of {@code rows} with an RMSE at most {@code rmse}, or null. */
    static Row cheapest(List<Row> rows, double rmse) {
        Row best = null;
        for (Row r : rows) {
            if (r.error().rmse <= rmse && (best == null || r.secondsMedian() < best.secondsMedian())) {
                best = r;
            }
        }
        return best;
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
                parts.add(e.getKey() + " needs " + r.setting().label() + String.format(Locale.ROOT, " (%s s)", seconds(r.secondsMedian())));
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
            return String.format(Locale.ROOT, "Adaptive does not reach the 4x4 grid's RMSE (%.3g) at the targets studied.", grid4.error().rmse);
        }
        return String.format(Locale.ROOT, "Adaptive reaches the 4x4 grid's RMSE (%.3g) with %s in %s s, %.2f of the grid's %s s (%.1f samples per pixel on average).",
                grid4.error().rmse, a.setting().label(), seconds(a.secondsMedian()), a.secondsMedian() / grid4.secondsMedian(),
                seconds(grid4.secondsMedian()), a.meanSpp());
    }

    /** Which sampler has the lowest RMSE at n_s = {@code ns} (equal samples per pixel). */
    static String equalSamplesSentence(SceneStudy.Outcome o, int ns) {
        List<String> parts = new ArrayList<>();
        String best = null;
        double bestRmse = Double.POSITIVE_INFINITY;
        for (Map.Entry<String, List<Row>> e : bySampler(o).entrySet()) {
            Row r = find(e.getValue(), "n_s=" + ns);
            if (r != null) {
                parts.add(String.format(Locale.ROOT, "%s %.3g", e.getKey(), r.error().rmse));
                if (r.error().rmse < bestRmse) {
                    bestRmse = r.error().rmse;
                    best = e.getKey();
                }
            }
        }
        if (parts.size() < 2) {
            return null;
        }
        return String.format(Locale.ROOT, "At %d samples per pixel the RMSE is %s: %s wins.", ns * ns, String.join(", ", parts), best);
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
        return s >= 10 ? String.format(Locale.ROOT, "%.1f", s) : s >= 0.1 ? String.format(Locale.ROOT, "%.2f", s)
                : String.format(Locale.ROOT, "%.3f", s);
    }

    static void html(List<SceneStudy.Outcome> outcomes, boolean honesty, String mode, double totalSeconds, ReportFolder dir, String file) throws IOException {
        StringBuilder b = new StringBuilder();
        b.append("<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Accuracy against time</title>\n")
                .append("<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em}")
                .append("table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}")
                .append("th{background:#f4f4f4}td:first-child,td:nth-child(2){text-align:left}img{max-width:100%}")
                .append("h2{margin-top:2em;border-top:1px solid #ddd;padding-top:1em}</style></head><body>\n")
                .append("<h1>What accuracy costs in time</h1>\n<p>Each scene was rendered with every sampler at every setting (")
                .append(esc(mode)).append("), timed in one process after a warm-up render (median and range of the repeats), and ")
                .append("compared with a converged reference on the clamped linear image. Errors are in units of the [0, 1] range; ")
                .append("one 8-bit step is 1/255 = 0.00392. Study time: ").append(seconds(totalSeconds)).append(" s.</p>\n");
        b.append("<h2>Summary</h2>\n<table><tr><th>scene</th><th>PSNR 40 dB</th><th>adaptive vs 4x4 grid</th>")
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
                    .append("<p><a href=\"").append(n).append(".csv\">").append(n).append(".csv</a></p>\n<table><tr>");
            for (String h : Row.HEADER.split(",")) {
                b.append("<th>").append(h).append("</th>");
            }
            b.append("</tr>\n");
            for (Row r : o.rows()) {
                b.append("<tr>");
                for (String cell : r.csv().split(",(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)")) {
                    b.append("<td>").append(esc(cell.replace("\"", ""))).append("</td>");
                }
                b.append("</tr>\n");
            }
            b.append("</table>\n");
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
