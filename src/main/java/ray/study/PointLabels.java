package ray.study;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.internal.chartpart.Annotation;

/**
 * Names beside the points of a plot, placed where they cover no other name and no point: each name is
 * tried right of its point, then left, above, below and at the corners, and goes right of it only when
 * every place is taken. Points of one curve that fall on one spot (MaxDepth 3, 4 and 5 of a scene whose
 * light dies out after three bounces) share one name ({@code d=3,4,5}). Placed when the chart is
 * painted, from the axes' own screen positions, so it holds for any axis range.
 */
final class PointLabels extends Annotation {

    /** A point in data coordinates, its name, and the curve it belongs to. */
    record Point(double x, double y, String name, String curve) {
    }

    /** Points of one curve closer than this (pixels) on both axes share one name. */
    static final int SAME_SPOT = 5;

    private final List<Point> points = new ArrayList<>();
    private final Font font;
    private final Color color;

    PointLabels(Font font, Color color) {
        super(false);
        this.font = font;
        this.color = color;
    }

    void add(double x, double y, String name, String curve) {
        points.add(new Point(x, y, name, curve));
    }

    @Override
    public void paint(Graphics2D g) {
        if (!isVisible || points.isEmpty()) {
            return;
        }
        Object aa = g.getRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(font);
        g.setColor(color);
        FontMetrics fm = g.getFontMetrics();
        int n = points.size();
        int[] sx = new int[n], sy = new int[n];
        for (int i = 0; i < n; i++) {
            sx[i] = getXAxisScreenValue(points.get(i).x());
            sy[i] = getYAxisScreenValue(points.get(i).y());
        }
        Rectangle2D plot = new Rectangle2D.Double(Math.min(getXAxisScreenValueForMin(), getXAxisScreenValueForMax()),
                Math.min(getYAxisScreenValueForMin(), getYAxisScreenValueForMax()),
                Math.abs(getXAxisScreenValueForMax() - getXAxisScreenValueForMin()),
                Math.abs(getYAxisScreenValueForMax() - getYAxisScreenValueForMin()));
        for (Placed p : place(points, sx, sy, plot, fm::stringWidth, fm.getAscent() + fm.getDescent())) {
            g.drawString(p.text(), (float) p.box().getX(), (float) p.box().getY() + fm.getAscent());
        }
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, aa);
    }

    /** A name and the box it is drawn in (screen pixels). */
    record Placed(String text, Rectangle2D box) {
    }

    /**
     * Where the names of {@code points} (at screen positions sx, sy) go inside {@code plot}, for text
     * {@code width(text)} wide and {@code h} high: see the class comment.
     */
    static List<Placed> place(List<Point> points, int[] sx, int[] sy, Rectangle2D plot, java.util.function.ToIntFunction<String> width, int h) {
        int n = points.size();
        List<Rectangle2D> taken = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            taken.add(new Rectangle2D.Double(sx[i] - 4, sy[i] - 4, 8, 8));    // the markers
        }
        List<Placed> out = new ArrayList<>();
        boolean[] done = new boolean[n];
        for (int i = 0; i < n; i++) {
            if (done[i]) {
                continue;
            }
            List<String> names = new ArrayList<>(List.of(points.get(i).name()));
            for (int j = i + 1; j < n; j++) {
                if (!done[j] && points.get(j).curve().equals(points.get(i).curve()) && Math.abs(sx[j] - sx[i]) <= SAME_SPOT
                        && Math.abs(sy[j] - sy[i]) <= SAME_SPOT) {
                    names.add(points.get(j).name());
                    done[j] = true;
                }
            }
            String text = joined(names);
            int w = width.applyAsInt(text);
            int[][] offsets = {{6, -h / 2}, {-6 - w, -h / 2}, {-w / 2, -h - 5}, {-w / 2, 5}, {5, -h - 3}, {5, 3}, {-5 - w, -h - 3},
                    {-5 - w, 3}, {14, -h / 2}, {-14 - w, -h / 2}, {-w / 2, -h - 13}, {-w / 2, 13}};
            Rectangle2D box = null;
            for (int[] o : offsets) {
                Rectangle2D b = new Rectangle2D.Double(sx[i] + o[0], sy[i] + o[1], w, h);
                // a gap of 3 pixels to any other name, so two names never read as one ("t=2" beside "4")
                Rectangle2D gap = new Rectangle2D.Double(b.getX() - 3, b.getY() - 1, b.getWidth() + 6, b.getHeight() + 2);
                if (plot.contains(b) && taken.stream().noneMatch(t -> t.intersects(gap))) {
                    box = b;
                    break;
                }
            }
            if (box == null) {
                box = new Rectangle2D.Double(sx[i] + offsets[0][0], sy[i] + offsets[0][1], w, h);
            }
            taken.add(box);
            out.add(new Placed(text, box));
        }
        return out;
    }

    /** {@code d=3,4,5} for d=3, d=4, d=5: the part before '=' once. */
    static String joined(List<String> names) {
        if (names.size() == 1) {
            return names.get(0);
        }
        int eq = names.get(0).indexOf('=');
        String prefix = eq < 0 ? "" : names.get(0).substring(0, eq + 1);
        StringBuilder b = new StringBuilder(prefix);
        for (int k = 0; k < names.size(); k++) {
            String s = names.get(k);
            b.append(k == 0 ? "" : ",").append(!prefix.isEmpty() && s.startsWith(prefix) ? s.substring(prefix.length()) : s);
        }
        return b.toString();
    }
}
