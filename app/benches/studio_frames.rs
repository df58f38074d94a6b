//! Frame CPU time of the studio, headless (egui layout and tessellation, no GPU): the first
//! frame on the example project, scrolling and typing in a 20,000-line POU, online with 500
//! values shown inline, and frames while a large program downloads.
//!
//! `cargo bench -p app --bench studio_frames` prints the figures; nothing is asserted.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench prints.

use std::time::{Duration, Instant};

use app::studio::{Phase, Settings, StudioApp, TreeNode};
use egui::{Event, Modifiers, MouseWheelUnit, Pos2, RawInput, Rect, Vec2};

const SIZE: Vec2 = Vec2::new(1280.0, 800.0);

/// One headless frame: layout and tessellation, as a window's frame costs on the CPU.
fn frame(ctx: &egui::Context, app: &mut StudioApp, events: Vec<Event>) -> Duration {
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SIZE)),
        events,
        ..RawInput::default()
    };
    let started = Instant::now();
    let output = ctx.run_ui(input, |ui| app.ui(ui));
    let _ = ctx.tessellate(output.shapes, output.pixels_per_point);
    started.elapsed()
}

/// The example project with Main's body and declarations replaced.
fn project_with_main(declarations: &str, body: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    std::fs::write(dir.path().join("application/Main.st"), body).unwrap();
    let pou = dir.path().join("application/Main.pou.toml");
    let text = std::fs::read_to_string(&pou).unwrap();
    std::fs::write(&pou, format!("{text}\n{declarations}")).unwrap();
    dir
}

fn summary(name: &str, times: &[Duration]) {
    let mut sorted: Vec<f64> = times.iter().map(|t| t.as_secs_f64() * 1000.0).collect();
    sorted.sort_by(f64::total_cmp);
    let median = sorted[sorted.len() / 2];
    let p95 = sorted[(sorted.len() * 95 / 100).min(sorted.len() - 1)];
    let max = sorted[sorted.len() - 1];
    println!(
        "{name}: median {median:.2} ms, 95th percentile {p95:.2} ms, max {max:.2} ms over {} frames",
        sorted.len()
    );
}

fn main() {
    // The first frame: opening the example project and drawing it once.
    let started = Instant::now();
    let ctx = egui::Context::default();
    let mut app = StudioApp::new(Settings::default(), Some(assets::example_project_dir()));
    frame(&ctx, &mut app, Vec::new());
    println!(
        "first frame (project loaded, fonts installed, drawn): {:.1} ms",
        started.elapsed().as_secs_f64() * 1000.0
    );
    let times: Vec<Duration> = (0..100)
        .map(|_| frame(&ctx, &mut app, Vec::new()))
        .collect();
    summary("idle frame, example project", &times);

    // A 20,000-line POU: scrolling and typing.
    let line = "GVL_Machine.udiTotalPackages := GVL_Machine.udiTotalPackages + 1; // 计数\n";
    let body: String = std::iter::repeat_n(line, 20_000).collect();
    let big = project_with_main("", &body);
    let ctx = egui::Context::default();
    let mut app = StudioApp::new(Settings::default(), Some(big.path().to_owned()));
    app.open(TreeNode::Object("Main".into()));
    for _ in 0..3 {
        frame(&ctx, &mut app, Vec::new());
    }
    let body_point = Pos2::new(640.0, 420.0);
    let click = |pressed| Event::PointerButton {
        pos: body_point,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    };
    frame(
        &ctx,
        &mut app,
        vec![Event::PointerMoved(body_point), click(true)],
    );
    frame(&ctx, &mut app, vec![click(false)]);
    let scrolling: Vec<Duration> = (0..300)
        .map(|_| {
            frame(
                &ctx,
                &mut app,
                vec![Event::MouseWheel {
                    unit: MouseWheelUnit::Line,
                    delta: Vec2::new(0.0, -3.0),
                    modifiers: Modifiers::NONE,
                    phase: egui::TouchPhase::Move,
                    source: egui::MouseWheelSource::Wheel,
                }],
            )
        })
        .collect();
    summary("scrolling a 20,000-line POU", &scrolling);
    let typing: Vec<Duration> = (0..300)
        .map(|i| {
            let c = if i % 10 == 9 { " " } else { "x" };
            frame(&ctx, &mut app, vec![Event::Text(c.to_owned())])
        })
        .collect();
    summary(
        "typing in a 20,000-line POU (each key an edit of the model)",
        &typing,
    );
    let typed = match app.session().map(|s| s.project.application.object("Main")) {
        Some(Some(project_model::Object::Pou(pou))) => pou.body.st_text().map_or(0, str::len),
        _ => 0,
    };
    println!(
        "  (the body grew by {} bytes while typing)",
        typed.saturating_sub(body.len())
    );

    // Online with 500 values inline: 250 variables, each read and written in the body.
    let declarations: String = (0..250)
        .map(|i| format!("[[variable]]\nname = \"v{i}\"\ntype = \"DINT\"\n\n"))
        .collect();
    let body: String = (0..250).map(|i| format!("v{i} := v{i} + {i};\n")).collect();
    let online = project_with_main(&declarations, &body);
    let ctx = egui::Context::default();
    let mut app = StudioApp::new(Settings::default(), Some(online.path().to_owned()));
    app.open(TreeNode::Object("Main".into()));
    frame(&ctx, &mut app, Vec::new());
    app.login(&ctx);
    let deadline = Instant::now() + Duration::from_secs(60);
    while !matches!(app.online().phase(), Phase::ConfirmDownload { .. })
        && Instant::now() < deadline
    {
        frame(&ctx, &mut app, Vec::new());
        std::thread::sleep(Duration::from_millis(5));
    }
    app.confirm_download();
    while *app.online().phase() != Phase::Online && Instant::now() < deadline {
        frame(&ctx, &mut app, Vec::new());
        std::thread::sleep(Duration::from_millis(5));
    }
    app.start();
    while app.inline_paths().len() < 250 || app.online().value("Main.v249").is_none() {
        assert!(Instant::now() < deadline, "the inline values never came");
        frame(&ctx, &mut app, Vec::new());
        std::thread::sleep(Duration::from_millis(5));
    }
    let refreshing: Vec<Duration> = (0..300)
        .map(|_| {
            std::thread::sleep(Duration::from_millis(3));
            frame(&ctx, &mut app, Vec::new())
        })
        .collect();
    summary(
        "online, 500 values inline refreshing every 100 ms",
        &refreshing,
    );

    // A large program downloading: the UI keeps drawing.
    let ctx = egui::Context::default();
    let big_program: String = std::iter::repeat_n(line, 20_000).collect();
    let large = project_with_main("", &big_program);
    let mut app = StudioApp::new(Settings::default(), Some(large.path().to_owned()));
    frame(&ctx, &mut app, Vec::new());
    app.login(&ctx);
    while !matches!(app.online().phase(), Phase::ConfirmDownload { .. })
        && Instant::now() < deadline + Duration::from_secs(60)
    {
        frame(&ctx, &mut app, Vec::new());
        std::thread::sleep(Duration::from_millis(5));
    }
    let size = app
        .last_build()
        .and_then(|b| b.image.as_ref())
        .map_or(0, |image| image.bytes.len());
    app.confirm_download();
    let mut during = Vec::new();
    let started = Instant::now();
    while *app.online().phase() != Phase::Online
        && Instant::now() < deadline + Duration::from_secs(120)
    {
        during.push(frame(&ctx, &mut app, Vec::new()));
        std::thread::sleep(Duration::from_millis(2));
    }
    println!(
        "download of a {size}-byte image took {:.0} ms",
        started.elapsed().as_secs_f64() * 1000.0
    );
    if !during.is_empty() {
        summary("frames during the download", &during);
    }
}
