using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Historian;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.TestKit;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Shell;
using Serilog;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>
/// A one-station line (station 2, CPU 224, on COM7) with a session on the manual clock, the simulated PLC behind a
/// <see cref="SimulatedLineConnector"/>, scripted dialogs and a collecting log. Triggered refresh unless told otherwise,
/// so nothing is polled but what a test asks for.
/// </summary>
internal sealed class PanelFixture : IAsyncDisposable
{
    public const string Port = "COM7";

    public static readonly Station Filler = new(2);

    public PanelFixture(PanelProject? project = null)
    {
        Connector = new SimulatedLineConnector(Clock);
        (Logger, Log) = CollectingSink.CreateLogger();
        // No inter-frame gap: the simulated port answers at once and the manual clock moves only when a station is silent.
        Session = new PanelSession(project ?? Project(), new InlineDispatcher(), Clock, Logger)
        {
            LinkOptionsFor = serial => Core.Link.V3.V3LinkOptions.For(serial) with { InterFrameGap = TimeSpan.Zero },
        };
    }

    public ManualTimeProvider Clock { get; } = new();

    public SimulatedLineConnector Connector { get; }

    public ScriptedDialogService Dialogs { get; } = new();

    public FakeFileDialogService Files { get; } = new();

    /// <summary>Writes unconfirmed, so a test answers only the questions it is about (the panel's default asks: PanelOptionsTests).</summary>
    public PanelOptions Options { get; } = new() { ConfirmWrites = false };

    public ILogger Logger { get; }

    public CollectingSink Log { get; }

    public PanelSession Session { get; }

    public SimulatedTransport Transport => Connector.Transport(Port);

    public Simulator.Reference.V3.ReferenceHandler Plc => Connector.Plc(Filler.Address);

    public static PanelProject Project(RefreshMode mode = RefreshMode.OnDemand, CpuProfile? cpu = null) =>
        new("Filler line", new RefreshSettings(mode, TimeSpan.FromMilliseconds(100)),
        [
            new ProjectStation(
                "Filler",
                Filler,
                cpu ?? CpuProfiles.For(CpuModel.Cpu224),
                new SerialSettings { PortName = Port },
                [Io("StartButton", "I0.0"), Io("StopButton", "I0.1"), Io("LevelHigh", "I1.2"), Io("Guard", "I0.5")],
                [Io("Conveyor", "Q0.0"), Io("Pump", "Q0.1")],
                [Tag("Speed", "VW10", DisplayFormat.Signed), Tag("Recipe", "MB4", DisplayFormat.Unsigned), Tag("Temperature", "VD20", DisplayFormat.Float)],
                []),
        ]);

    /// <summary>This fixture's own history folder (a temp folder, deleted on dispose).</summary>
    public HistoryFolder HistoryFolder { get; } = new(System.IO.Path.Combine(System.IO.Path.GetTempPath(), "opanel-vm-history-" + Guid.NewGuid().ToString("N")));

    public FakeAlarmSound Sound { get; } = new();

    public static ShellServices Services(PanelFixture fixture, IDemoSource? demo = null) =>
        new(fixture.Dialogs, fixture.Files, fixture.Connector, demo, new StarterProjectSource(), History: fixture.HistoryFolder, Sound: fixture.Sound);

    public ShellViewModel Shell(IDemoSource? demo = null) => new(Session, Options, Services(this, demo), Clock, Logger);

    public Task ConnectAsync() => Session.ConnectAsync(Connector).Guarded();

    public Task RefreshAsync() => Session.RefreshNowAsync().Guarded();

    public async ValueTask DisposeAsync()
    {
        await Session.DisposeAsync();
        if (Directory.Exists(HistoryFolder.Path))
        {
            Directory.Delete(HistoryFolder.Path, recursive: true);
        }
    }

    private static IoSymbol Io(string symbol, string address) => new(symbol, PlcAddress.Parse(address), symbol + " comment");

    private static ProjectTag Tag(string symbol, string address, DisplayFormat format) =>
        new(symbol, PlcAddress.Parse(address), format, Writable: true, Description: string.Empty);
}
