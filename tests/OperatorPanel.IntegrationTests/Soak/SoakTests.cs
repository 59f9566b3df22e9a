using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Soak;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using OperatorPanel.TestKit;
using Xunit.Abstractions;

namespace OperatorPanel.IntegrationTests.Soak;

/// <summary>
/// The short soak (docs/soak.md): the real panel stack (protocol v3) writes and reads the ends of I, Q, M, SM and of the
/// V below the handler (<see cref="SoakRegion.AreaEnds"/>, besides VD1000 and VD1004) through the noisy-line proxy in
/// front of the generated v3 handler in the STL interpreter, while the field changes the last I and SM bytes, and the
/// judge holds every good value and every confirmed write against what the PLC did. Real time; the counts vary with the
/// machine's speed and the faults make most exchanges fail, so only the zeros and floors on the work done are asserted.
/// `opanel soak` runs it for longer.
/// </summary>
public sealed class SoakTests(ITestOutputHelper output)
{
    private const int Baud = 19200;
    private static readonly CpuProfile Cpu = CpuProfiles.For(CpuModel.Cpu226);
    private static readonly HandlerOptions Options = new() { Cpu = Cpu, Station = 2, BaudRate = Baud, Protocol = 3 };

    [Theory]
    [InlineData("flips")]
    [InlineData("mixed")]
    public async Task NoisyLine_NoWrongValueShownGoodNoFalseConfirmationNoWriteOutOfOrder(string profile)
    {
        LineFaults.TryFind(profile, out var faults, out var error).Should().BeTrue(error);

        // 16 s: a lost READ LIST reply costs its 1.5 s time-out (48 handler scans at 30 ms), and the list of the area ends
        // (32 data bytes) is lost more often than the 8 bytes of VD1000/VD1004 were; in 12 s the mixed profile made 10.
        var figures = await RunAsync(faults!, TimeSpan.FromSeconds(16), TimeSpan.FromMilliseconds(5));

        var because = string.Join(Environment.NewLine, figures.Text());
        figures.WrongValuesShownGood.Should().Be(0, because);
        figures.FalseConfirmations.Should().Be(0, because);
        figures.WritesOutOfOrder.Should().Be(0, because);
        figures.Exchanges.Should().BeGreaterThanOrEqualTo(6, because);
    }

    /// <summary>
    /// The judge's other side, and the workload's reach: on a clean line the handler is identified (so its list is polled
    /// with READ LIST, as the panel does), every write is confirmed and executed, every address of the region is shown
    /// good and every written one confirmed, and the field's I and SM changes reached the PLC.
    /// </summary>
    [Fact]
    public async Task CleanLine_IdentifiedEveryWriteConfirmedAndEveryAreaEndShownAndWritten()
    {
        // No machine program here: every write must be confirmed, and on a loaded 2-core machine the interpreter running
        // a 5 ms program in real time fell behind (timeouts) while the noisy runs above only count what went through.
        var figures = await RunAsync(LineFaults.Clean, TimeSpan.FromSeconds(6), TimeSpan.Zero);

        var because = string.Join(Environment.NewLine, figures.Text());
        var region = SoakRegion.AreaEnds(Cpu, Options.EffectiveV3First);
        figures.Region.Should().Be(region.ToString());
        figures.LinesIdentified.Should().Be(1, because);
        figures.WritesConfirmed.Should().Be(figures.WritesSent, because).And.BeGreaterThan(region.Written.Length, because);
        figures.ShownGoodByItem.Keys.Should().BeEquivalentTo(region.Items.Select(a => a.ToString()), because);
        figures.ConfirmedByItem.Keys.Should().BeEquivalentTo(region.Written.Select(a => a.ToString()), because);
        figures.FieldChanges.Should().BeGreaterThanOrEqualTo(4, because);
        figures.ExecutedNeverSent.Should().Be(0, because);
        figures.ZerosHold.Should().BeTrue(because);
    }

    private async Task<SoakFigures> RunAsync(LineFaults faults, TimeSpan duration, TimeSpan userProgram)
    {
        using var panelPair = await SocatPtyPair.StartAsync();
        using var plcPair = await SocatPtyPair.StartAsync();
        var generated = HandlerGenerator.Generate(Options);
        generated.Ok.Should().BeTrue(string.Join("; ", generated.Diagnostics));
        var settings = new LineSettings(Baud, Core.Transport.Parity.None, 8);
        StlStation.TryCreate(generated.AwlText, Cpu, 0, settings, out var station, out var error).Should().BeTrue(error);
        // The machine's program beside the handler (5 ms a scan in the noisy runs, as on a real line and as bench link assumes).
        station!.Plc.UserProgramTime = userProgram;
        var line = new StlLine(settings);
        line.Attach(station, runProcess: false);

        var figures = await SoakSession.RunAsync(
            new SoakSetup
            {
                PanelPort = panelPair.PathA,
                ProxyPanelSide = panelPair.PathB,
                ProxyPlcSide = plcPair.PathA,
                PlcPort = plcPair.PathB,
                Baud = Baud,
                Faults = faults,
                Seed = 11,
                Duration = duration,
                Station = new Station(2),
                Cpu = Cpu,
                Line = line,
                Memory = station!.Memory,
                HandlerFirstByte = Options.EffectiveV3First,
                Inputs = station.Plc.InputImage,
            },
            TimeProvider.System,
            log: null,
            CancellationToken.None);
        foreach (var text in figures.Text())
        {
            output.WriteLine(text);
        }

        return figures;
    }
}
