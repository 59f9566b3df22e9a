using OperatorPanel.Cli.Watch;
using OperatorPanel.TestKit;
using Serilog.Core;
using Spectre.Console.Testing;

namespace OperatorPanel.Cli.Tests.Watch;

/// <summary>When watch prints, on simulated time.</summary>
public sealed class LiveOutputTests : IDisposable
{
    private readonly ManualTimeProvider _time = new();
    private readonly StringWriter _out = new();

    [Fact]
    public void CycleCompleted_NotATerminalOpenEnded_AppendsOncePerSecond()
    {
        var output = new LiveOutput(Context(terminal: false), everyCycle: false, _time);

        for (var i = 0; i < 25; i++)
        {
            output.CycleCompleted(() => Snapshot(i));
            _time.Advance(TimeSpan.FromMilliseconds(100));
        }

        Headers().Should().Equal("cycle 0", "cycle 10", "cycle 20");
    }

    [Fact]
    public void CycleCompleted_CountedCycles_AppendsEveryCycle()
    {
        var output = new LiveOutput(Context(terminal: false), everyCycle: true, _time);

        output.CycleCompleted(() => Snapshot(1));
        output.CycleCompleted(() => Snapshot(2));

        Headers().Should().Equal("cycle 1", "cycle 2");
        _out.ToString().Should().NotContain("\u001b[");
    }

    [Fact]
    public void CycleCompleted_Terminal_DrawsFramesInPlaceAtMostFiveTimesASecondAndShowsTheLastAtTheEnd()
    {
        var frames = new List<string>();
        var output = new LiveOutput(Context(terminal: true), everyCycle: true, _time, frame => frames.Add(Text(frame)), () => (80, 24));

        for (var i = 1; i <= 10; i++)
        {
            output.CycleCompleted(() => Snapshot(i));
            _time.Advance(TimeSpan.FromMilliseconds(50));
        }

        output.Finish(() => Snapshot(10));

        frames.Select(f => f[f.IndexOf("cycle", StringComparison.Ordinal)..].Split("  ")[0]).Should().Equal("cycle 1", "cycle 5", "cycle 9", "cycle 10");
        _out.ToString().Should().BeEmpty("the live display draws the frames, nothing is appended");
    }

    public void Dispose() => _out.Dispose();

    private CliContext Context(bool terminal) => new(_out, TextWriter.Null, Json: false, Logger.None) { IsTerminal = terminal };

    private static string Text(Spectre.Console.Rendering.IRenderable frame)
    {
        var console = new TestConsole().Width(80);
        console.Write(frame);
        return console.Output;
    }

    private static WatchSnapshot Snapshot(long cycle) => new("Line", "continuous", cycle, DateTimeOffset.UnixEpoch, []);

    private string[] Headers() =>
        [.. _out.ToString().Split('\n').Where(l => l.Contains("Line  (", StringComparison.Ordinal)).Select(l => l[l.IndexOf("cycle", StringComparison.Ordinal)..].Split("  ")[0])];
}
