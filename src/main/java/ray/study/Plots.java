package ray.study;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;
import ray.render.Image;

/** The study's pictures: error against time, the adaptive estimate against the truth, and crops. */
final class Plots {

    private Plots() {
    }

    /**
     * RMSE (8-bit steps) against median CPU time on log-log axes, one curve per sampler (the MaxDepth rows
     * apart), each point labelled with its setting; every power of ten and the 2 and 5 between them are
     * labelled on both axes, with lines at one step and at PSNR 40 dB.
     */
    static void errorVersusTime(SceneStudy.Outcome o, ReportFolder dir, String png) throws IOException {
        boolean cpu = o.rows().stream().noneMatch(r -> Double.isNaN(r.cpuMedian()));
        XYChart c = new XYChartBuilder().width(860).height(540).title(o.name() + ": error against time")
                .xAxisTitle(cpu ? "CPU time (s, median of repeats; all threads)" : "wall time (s, median of repeats)")
                .yAxisTitle("RMSE (8-bit steps)").build();
        c.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true).setLegendPosition(Styler.LegendPosition.OutsideE)
                .setChartBackgroundColor(Color.WHITE).setMarkerSize(7);
        c.getStyler().setXAxisLogarithmicDecadeOnly(false).setYAxisLogarithmicDecadeOnly(false);
        c.setCustomXAxisTickLabelsFormatter(Plots::oneTwoFive);
        c.setCustomYAxisTickLabelsFormatter(Plots::oneTwoFive);
        PointLabels labels = new PointLabels(new Font(Font.SANS_SERIF, Font.PLAIN, 10), Color.DARK_GRAY);
        double ylo = Double.POSITIVE_INFINITY, yhi = 0;
        Map<String, List<Row>> curves = new LinkedHashMap<>();
        for (Row r : o.rows()) {
            String key = isDepthRow(r, o) ? "MaxDepth (grid n_s=" + r.setting().ns() + ")" : r.setting().sampler();
            curves.computeIfAbsent(key, k -> new ArrayList<>()).add(r);
        }
        boolean any = false;
        double lo = Double.POSITIVE_INFINITY, hi = 0;
        for (Map.Entry<String, List<Row>> e : curves.entrySet()) {
            List<Row> rs = new ArrayList<>();
            for (Row r : e.getValue()) {
                if (r.error().rmse > 0 && r.cost() > 0) {
                    rs.add(r);
                }
            }
            if (rs.isEmpty()) {
                continue;
            }
            // in setting order (more samples, or a deeper MaxDepth, along each curve), not by time, which is noisy
            XYSeries s = c.addSeries(e.getKey(), rs.stream().mapToDouble(Row::cost).toArray(),
                    rs.stream().mapToDouble(Row::rmseSteps).toArray());
            s.setMarker(SeriesMarkers.CIRCLE);
            for (Row r : rs) {
                labels.add(r.cost(), r.rmseSteps(), shortLabel(r), e.getKey());
                lo = Math.min(lo, r.cost());
                hi = Math.max(hi, r.cost());
                ylo = Math.min(ylo, r.rmseSteps());
                yhi = Math.max(yhi, r.rmseSteps());
            }
            any = true;
        }
        if (!any) {
            write(note(o.name() + ": every setting matches the reference exactly"), dir, png);
            return;
        }
        // both axes from a labelled value to a labelled value (1, 2 or 5 times a power of ten), so no end of an axis goes unnamed
        double[] xs = {oneTwoFiveBelow(lo / 1.2), oneTwoFiveAbove(hi * 1.25)};
        double psnr40 = Math.pow(10, -Report.TARGET_PSNR_DB / 20) / ImageError.STEP;
        c.getStyler().setXAxisMin(xs[0]).setXAxisMax(xs[1]).setYAxisMin(oneTwoFiveBelow(Math.min(ylo / 1.1, 0.9)))
                .setYAxisMax(oneTwoFiveAbove(Math.max(yhi * 1.1, psnr40 * 1.1)));
        XYSeries line = c.addSeries("one 8-bit step", xs, new double[] {1, 1});
        line.setMarker(SeriesMarkers.NONE).setLineColor(Color.GRAY)
                .setLineStyle(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 4f}, 0f));
        XYSeries target = c.addSeries("PSNR 40 dB (" + String.format(java.util.Locale.ROOT, "%.2f", psnr40) + " steps)", xs,
                new double[] {psnr40, psnr40});
        target.setMarker(SeriesMarkers.NONE).setLineColor(new Color(0xb00020))
                .setLineStyle(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {8f, 4f}, 0f));
        c.addAnnotation(labels);
        write(BitmapEncoder.getBufferedImage(c), dir, png);
    }

    /** The largest of 1, 2 and 5 times a power of ten at most {@code v} (v > 0). */
    static double oneTwoFiveBelow(double v) {
        double p = Math.pow(10, Math.floor(Math.log10(v)));
        double m = v / p;
        return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
    }

    /** The smallest of 1, 2 and 5 times a power of ten at least {@code v} (v > 0). */
    static double oneTwoFiveAbove(double v) {
        double p = Math.pow(10, Math.floor(Math.log10(v)));
        double m = v / p;
        return (m <= 1 + 1e-9 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
    }

    /**
     * A log axis's tick label: 1, 2 and 5 times a power of ten are written (0.02, 0.05, 0.1, 0.2 ...), the
     * ticks between them left blank, so every decade is labelled without the labels running together.
     */
    static String oneTwoFive(Double v) {
        if (v == null || !(v > 0)) {
            return "";
        }
        double e = Math.floor(Math.log10(v) + 1e-9), m = v / Math.pow(10, e);
        boolean shown = Math.abs(m - 1) < 1e-6 || Math.abs(m - 2) < 1e-6 || Math.abs(m - 5) < 1e-6 || Math.abs(m - 10) < 1e-5;
        return shown ? new java.math.BigDecimal(v).round(new java.math.MathContext(1)).stripTrailingZeros().toPlainString() : "";
    }

    /**
     * {@code 4} for n_s=4, {@code t=0.5} for target=0.5, {@code d=3} for MaxDepth=3 (its n_s is in the
     * curve's name): short enough to sit beside a point.
     */
    static String shortLabel(Row r) {
        String l = r.setting().label();
        if (l.startsWith("MaxDepth=")) {
            return "d=" + r.setting().maxDepth();
        }
        return l.replace("n_s=", "").replace("target=", "t=");
    }

    /** The honesty plot names its points (t=1 ...) up to this many; the per-scene tables name every one. */
    static final int MAX_NAMED = 40;

    /** The adaptive sampler's own error estimate against its true RMSE, all scenes in one plot, each point named up to {@link #MAX_NAMED}. */
    static boolean honesty(List<SceneStudy.Outcome> outcomes, ReportFolder dir, String png) throws IOException {
        // tall enough for a legend line per scene
        XYChart c = new XYChartBuilder().width(760).height(Math.max(520, 21 * outcomes.size() + 140))
                .title("adaptive: estimated against true image error")
                .xAxisTitle("true RMSE (against the reference, its own noise taken out; 8-bit steps)").yAxisTitle("estimated RMSE (8-bit steps)").build();
        c.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true).setLegendPosition(Styler.LegendPosition.OutsideE)
                .setChartBackgroundColor(Color.WHITE).setMarkerSize(7);
        c.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        c.getStyler().setXAxisLogarithmicDecadeOnly(false).setYAxisLogarithmicDecadeOnly(false);
        c.setCustomXAxisTickLabelsFormatter(Plots::oneTwoFive);
        c.setCustomYAxisTickLabelsFormatter(Plots::oneTwoFive);
        double lo = Double.POSITIVE_INFINITY, hi = 0;
        boolean any = false;
        PointLabels labels = new PointLabels(new Font(Font.SANS_SERIF, Font.PLAIN, 10), Color.DARK_GRAY);
        int named = 0;
        for (SceneStudy.Outcome o : outcomes) {
            List<double[]> pts = new ArrayList<>();
            for (Row r : o.rows()) {
                double truth = o.ref().trueSteps(r.rmseSteps());
                if (!Double.isNaN(r.estimatedRmseSteps()) && truth > 0 && r.estimatedRmseSteps() > 0) {
                    pts.add(new double[] {truth, r.estimatedRmseSteps()});
                    labels.add(truth, r.estimatedRmseSteps(), shortLabel(r), o.name());
                    named++;
                    lo = Math.min(lo, Math.min(truth, r.estimatedRmseSteps()));
                    hi = Math.max(hi, Math.max(truth, r.estimatedRmseSteps()));
                }
            }
            if (!pts.isEmpty()) {
                c.addSeries(o.name(), pts.stream().mapToDouble(p -> p[0]).toArray(), pts.stream().mapToDouble(p -> p[1]).toArray());
                any = true;
            }
        }
        if (!any) {
            return false;
        }
        double[] xs = {oneTwoFiveBelow(lo / 1.5), oneTwoFiveAbove(hi * 1.5)};
        c.getStyler().setXAxisMin(xs[0]).setXAxisMax(xs[1]).setYAxisMin(oneTwoFiveBelow(xs[0] / 1.5)).setYAxisMax(oneTwoFiveAbove(xs[1] * 1.5));
        guide(c, "estimate = truth", xs, 1, new float[] {1f, 0f});
        guide(c, "x 1.5", xs, 1.5, new float[] {5f, 4f});
        guide(c, "/ 1.5", xs, 1 / 1.5, new float[] {5f, 4f});
        if (named <= MAX_NAMED) {       // beyond that the names would cover each other; each scene's table names them
            c.addAnnotation(labels);
        }
        write(BitmapEncoder.getBufferedImage(c), dir, png);
        return true;
    }

    private static void guide(XYChart c, String name, double[] xs, double factor, float[] dash) {
        XYSeries s = c.addSeries(name, xs, new double[] {xs[0] * factor, xs[1] * factor});
        s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        s.setMarker(SeriesMarkers.NONE).setLineColor(Color.DARK_GRAY)
                .setLineStyle(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                        dash[1] == 0 ? null : dash, 0f));
    }

    /**
     * The worst region of the cheapest grid render (a square of about a fifth of the image's short side,
     * where that render's error is largest), cut from every grid setting and the reference and shown
     * magnified side by side, each labelled with its setting and RMSE over the crop.
     */
    static void crops(SceneStudy.Outcome o, ReportFolder dir, String png) throws IOException {
        List<Integer> idx = new ArrayList<>();
        for (int i = 0; i < o.rows().size(); i++) {
            Row r = o.rows().get(i);
            if (r.setting().sampler().equals("grid") && !isDepthRow(r, o)) {
                idx.add(i);
            }
        }
        Image ref = o.reference();
        int size = Math.max(8, Math.min(48, Math.min(ref.width, ref.height) / 5));
        int[] at = idx.isEmpty() ? new int[] {0, 0} : worstWindow(ImageError.perPixel(o.images().get(idx.get(0)), ref), ref.width, ref.height, size);
        int zoom = Math.max(2, 160 / size), cell = size * zoom, label = 34;
        int cols = idx.size() + 1;
        BufferedImage out = new BufferedImage(cols * (cell + 8) + 8, cell + label + 16, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, out.getWidth(), out.getHeight());
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        for (int k = 0; k < cols; k++) {
            Image img = k < idx.size() ? o.images().get(idx.get(k)) : ref;
            String title = k < idx.size() ? o.rows().get(idx.get(k)).setting().label() : "reference";
            BufferedImage crop = img.toBufferedImage().getSubimage(at[0], at[1], Math.min(size, ref.width - at[0]), Math.min(size, ref.height - at[1]));
            int x = 8 + k * (cell + 8);
            g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
            g.drawImage(crop, x, 8, crop.getWidth() * zoom, crop.getHeight() * zoom, null);
            g.setColor(Color.BLACK);
            g.drawString(title, x, cell + 24);
            if (k < idx.size()) {
                g.drawString(String.format("crop RMSE %.2f steps", cropRmse(img, ref, at, size) / ImageError.STEP), x, cell + 38);
            }
        }
        g.dispose();
        write(out, dir, png);
    }

    private static double cropRmse(Image img, Image ref, int[] at, int size) {
        double s = 0;
        int n = 0;
        for (int y = at[1]; y < Math.min(ref.height, at[1] + size); y++) {
            for (int x = at[0]; x < Math.min(ref.width, at[0] + size); x++) {
                for (int c = 0; c < 3; c++) {
                    int i = 3 * (y * ref.width + x) + c;
                    double d = ImageError.clamp(img.rgb[i]) - ImageError.clamp(ref.rgb[i]);
                    s += d * d;
                    n++;
                }
            }
        }
        return Math.sqrt(s / n);
    }

    /** Top-left corner of the size x size window with the largest summed error (summed-area table). */
    static int[] worstWindow(double[] err, int w, int h, int size) {
        size = Math.min(size, Math.min(w, h));
        double[] sat = new double[(w + 1) * (h + 1)];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                sat[(y + 1) * (w + 1) + x + 1] = err[y * w + x] + sat[y * (w + 1) + x + 1] + sat[(y + 1) * (w + 1) + x] - sat[y * (w + 1) + x];
            }
        }
        double best = -1;
        int[] at = {0, 0};
        for (int y = 0; y + size <= h; y++) {
            for (int x = 0; x + size <= w; x++) {
                double s = sat[(y + size) * (w + 1) + x + size] - sat[y * (w + 1) + x + size] - sat[(y + size) * (w + 1) + x] + sat[y * (w + 1) + x];
                if (s > best) {
                    best = s;
                    at = new int[] {x, y};
                }
            }
        }
        return at;
    }

    static boolean isDepthRow(Row r, SceneStudy.Outcome o) {
        return r.setting().label().startsWith("MaxDepth=");
    }

    private static BufferedImage note(String text) {
        BufferedImage img = new BufferedImage(760, 80, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 760, 80);
        g.setColor(Color.BLACK);
        g.drawString(text, 16, 44);
        g.dispose();
        return img;
    }

    static void write(BufferedImage img, ReportFolder dir, String png) throws IOException {
        dir.write(png, out -> {
            if (!ImageIO.write(img, "png", out)) {
                throw new IOException("no PNG writer");
            }
        });
    }
}
