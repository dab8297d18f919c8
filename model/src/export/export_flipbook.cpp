// The HTML flipbook: one file that plays the animation anywhere. Every drawing is embedded
// once as a PNG data URL with its hold; a small inline script plays them at the document's
// rate with play/pause, loop and a scrubber over the ticks. A Content-Security-Policy forbids
// any network access, so the page works offline and cannot load anything it does not hold.
// A soundtrack is embedded as a WAV data URL (export_sound.h) and plays with the frames once
// the viewer presses Play (browsers refuse sound before a click); it is silent while paused or
// scrubbed, and starts again where the frames are whenever playing (re)starts or loops.
#include "export_formats.h"
#include "export_sound.h"
#include "export_text.h"
#include "pending_output.h"
#include "target_lock.h"

#include <QFileInfo>

namespace finbook::model {

namespace {
// The player. Time decides the tick (floor(elapsed × fps) past where this run started), as in
// the editor's playback, so a late timer delays one change instead of the whole animation.
// window.flipbook lets tests and other pages drive it; "#paused" in the address opens it
// paused on the first frame.
constexpr char kScript[] = R"JS(
"use strict";
(function () {
  const starts = [];
  let total = 0;
  for (const h of holds) { starts.push(total); total += h; }
  const canvas = document.getElementById("stage");
  const ctx = canvas.getContext("2d");
  const button = document.getElementById("play");
  const loopBox = document.getElementById("loop");
  const scrub = document.getElementById("scrub");
  const counter = document.getElementById("counter");
  let playing = false, tick = 0, baseTick = 0, origin = 0, timer = 0, shown = -1;
  const images = frames.map((src, i) => {
    const img = new Image();
    img.onload = () => { if (frameAt(tick) === i) { shown = -1; show(tick); } };
    img.src = src;
    return img;
  });
  function frameAt(t) {
    let lo = 0, hi = starts.length - 1;
    while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (starts[mid] <= t) lo = mid; else hi = mid - 1; }
    return lo;
  }
  function show(t) {
    tick = t;
    const f = frameAt(t);
    scrub.value = String(t);
    counter.value = (f + 1) + " / " + frames.length;
    if (f !== shown && images[f].complete && images[f].naturalWidth > 0) {
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.drawImage(images[f], 0, 0);
      shown = f;
    }
  }
  const sound = document.getElementById("sound");
  function syncSound() {
    if (!sound) return;
    if (!playing) { sound.pause(); return; }
    sound.currentTime = tick / fps;
    const started = sound.play();
    if (started) started.catch(() => {});
  }
  function restart() { baseTick = tick; origin = performance.now(); syncSound(); }
  function step() {
    clearTimeout(timer);
    if (!playing) return;
    const elapsed = Math.floor((performance.now() - origin) * fps / 1000);
    let t = baseTick + elapsed;
    if (t >= total) {
      if (!loopBox.checked) { show(total - 1); setPlaying(false); return; }
      t %= total;
      // The sound starts again with the frames: so does the clock.
      if (sound) { show(t); restart(); timer = setTimeout(step, 1000 / fps); return; }
    }
    show(t);
    const due = origin + (elapsed + 1) * 1000 / fps;
    timer = setTimeout(step, Math.max(0, due - performance.now()));
  }
  function setPlaying(p) {
    playing = p;
    button.textContent = p ? labels.pause : labels.play;
    button.setAttribute("aria-pressed", p ? "true" : "false");
    if (p) {
      if (tick >= total - 1 && !loopBox.checked) tick = 0;
      restart();
      step();
    } else {
      clearTimeout(timer);
      syncSound();
    }
  }
  button.addEventListener("click", () => setPlaying(!playing));
  loopBox.addEventListener("change", () => { if (playing) { restart(); step(); } });
  scrub.addEventListener("input", () => { show(Number(scrub.value)); restart(); });
  document.addEventListener("keydown", (e) => {
    if (e.target === scrub && e.key !== " ") return;
    if (e.key === " ") { e.preventDefault(); setPlaying(!playing); }
    else if (e.key === "ArrowRight" || e.key === "ArrowLeft") {
      setPlaying(false);
      const f = Math.max(0, Math.min(frames.length - 1, frameAt(tick) + (e.key === "ArrowRight" ? 1 : -1)));
      show(starts[f]);
    }
  });
  scrub.max = String(total - 1);
  window.flipbook = {
    get tick() { return tick; }, get frame() { return frameAt(tick); },
    get shown() { return shown; }, get playing() { return playing; }, ticks: total,
    get sound() { return sound ? { time: sound.currentTime, paused: sound.paused, duration: sound.duration } : null; },
    play: () => setPlaying(true), pause: () => setPlaying(false), seek: (t) => { show(t); restart(); }
  };
  show(0);
  // "#paused" opens on the first frame without playing (for embedding, and for tests).
  if (location.hash === "#paused") setPlaying(false); else setPlaying(true);
})();
)JS";

QByteArray escaped(const QString &text)
{
    return text.toHtmlEscaped().toUtf8();
}

QByteArray jsString(const QString &text)
{
    QByteArray out = "\"";
    for (const QChar c : text) {
        if (c == QLatin1Char('"') || c == QLatin1Char('\\') || c == QLatin1Char('<') ||
            c.unicode() < 0x20)
            out += "\\u" + QByteArray::number(c.unicode(), 16).rightJustified(4, '0');
        else
            out += QString(c).toUtf8();
    }
    return out + '"';
}

QByteArray styleSheet(const ExportPlan &plan)
{
    // Transparent frames show over a checkerboard, as image editors show transparency.
    const QByteArray behind =
        plan.transparent
            ? "background:repeating-conic-gradient(#ccc 0 25%,#fff 0 50%) 0 0/16px 16px;"
            : "background:" + QColor::fromRgb(plan.background).name().toLatin1() + ';';
    return "html,body{margin:0;background:#f3f3f3;color:#222;font:14px system-ui,sans-serif}"
           "#stage{display:block;max-width:100%;height:auto;" +
           behind +
           "}"
           "#bar{display:flex;align-items:center;gap:10px;padding:8px;max-width:" +
           QByteArray::number(plan.size.width()) +
           "px;box-sizing:border-box}"
           "#scrub{flex:1;min-width:60px}#play{min-width:5em}";
}
} // namespace

QByteArray flipbookHtml(const std::vector<QByteArray> &pngs, const ExportPlan &plan,
                        const QString &title, const QByteArray &soundWav)
{
    QByteArray frames = "[";
    for (std::size_t i = 0; i < pngs.size(); ++i)
        frames += (i ? ",\n\"" : "\n\"") + QByteArray("data:image/png;base64,") +
                  pngs[i].toBase64() + '"';
    frames += "]";
    QByteArray holds = "[";
    for (std::size_t i = 0; i < plan.holds.size(); ++i)
        holds += (i ? "," : "") + QByteArray::number(plan.holds[i]);
    holds += "]";
    const QString name = title.isEmpty() ? Export::tr("Flipbook") : title;

    QByteArray html = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n";
    html += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
            "img-src data:; " +
            QByteArray(soundWav.isEmpty() ? "" : "media-src data:; ") +
            "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n";
    html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    html += "<meta name=\"generator\" content=\"Finbook\">\n";
    html += "<title>" + escaped(name) + "</title>\n<style>" + styleSheet(plan) + "</style>\n";
    html += "</head><body>\n<canvas id=\"stage\" width=\"" + QByteArray::number(plan.size.width()) +
            "\" height=\"" + QByteArray::number(plan.size.height()) + "\"></canvas>\n";
    html += "<div id=\"bar\"><button id=\"play\" type=\"button\">" + escaped(Export::tr("Play")) +
            "</button>\n<label><input id=\"loop\" type=\"checkbox\"" +
            (plan.loop ? " checked" : "") + "> " + escaped(Export::tr("Loop")) + "</label>\n";
    html += "<input id=\"scrub\" type=\"range\" min=\"0\" max=\"0\" value=\"0\" step=\"1\" "
            "aria-label=\"" +
            escaped(Export::tr("Frame")) + "\">\n<output id=\"counter\">1 / " +
            QByteArray::number(qulonglong(pngs.size())) + "</output></div>\n";
    if (!soundWav.isEmpty())
        html += "<audio id=\"sound\" preload=\"auto\" src=\"data:audio/wav;base64," +
                soundWav.toBase64() + "\"></audio>\n";
    html += "<script>\nconst fps = " + QByteArray::number(plan.fps) + ";\nconst holds = " + holds +
            ";\nconst labels = {play: " + jsString(Export::tr("Play")) +
            ", pause: " + jsString(Export::tr("Pause")) + "};\nconst frames = " + frames + ";\n";
    html += kScript;
    html += "</script>\n</body></html>\n";
    return html;
}

ExportOutcome exportFlipbook(const ExportContext &context)
{
    const QString target = context.options.target;
    if (auto error = checkFileTarget(context.options))
        return unexpected(*error);
    FolderGuard guard(QFileInfo(target).path());
    TargetLock lock(target, false);
    if (auto error = claimFileTarget(target, guard, {&lock}))
        return unexpected(*error);

    const ExportPlan &plan = context.plan;
    std::vector<QByteArray> pngs;
    const qint64 total = qint64(plan.frames.size());
    for (std::size_t i = 0; i < plan.frames.size(); ++i) {
        pngs.push_back(context.png(i));
        if (pngs.back().isEmpty())
            return unexpected(
                writeFailed(target, Export::tr("there is not enough memory to render it")));
        if (context.cancelled(qint64(i) + 1, total))
            return unexpected(cancelledError());
    }
    const QByteArray html =
        flipbookHtml(pngs, plan, context.options.title,
                     context.sound.carriesSound() ? context.sound.flipbookWav() : QByteArray());
    PendingFile pending(target);
    QString reason;
    if (!pending.open(&reason))
        return unexpected(writeFailed(target, reason));
    if (auto failed = writeSynced(pending.file(), html))
        return unexpected(writeFailed(target, *failed));
    if (auto error = commitFile(pending, context.options))
        return unexpected(*error);
    guard.keep();

    ExportResult result;
    result.files << target;
    result.fileCount = 1;
    result.images = total;
    result.ticks = plan.ticks;
    result.size = plan.size;
    return result;
}

} // namespace finbook::model
