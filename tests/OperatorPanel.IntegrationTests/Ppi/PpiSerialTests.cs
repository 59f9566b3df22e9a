using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using OperatorPanel.TestKit;

namespace OperatorPanel.IntegrationTests.Ppi;

/// <summary>
/// The panel's PPI master over a socat pty to simulated S7-200s, in real time: SerialPortTransport (8 data bits, even
/// parity) -> pty -> SimulatedPlcHost -> the CPU's PPI side on the memory its program runs on.
/// </summary>
public sealed class PpiSerialTests
{
    private const int Baud = 19200;
    private static readonly CpuProfile Cpu = CpuProfiles.For(CpuModel.Cpu226);
    private static readonly LineSettings PpiLine = new(Baud, Parity.Even, 8);

    /// <summary>A loaded 2-core machine can stall a thread for a while: wide time-outs, so each test sees one exchange per job.</summary>
    private static readonly PpiMasterOptions Options = PpiMasterOptions.ForBaud(Baud) with
    {
        ReplyTimeout = TimeSpan.FromMilliseconds(800),
        AnswerTimeout = TimeSpan.FromSeconds(5),
    };

    [Fact]
    public async Task ReadAndWrite_NoHandlerLoaded_ReachTheCpusMemory()
    {
        var line = new StlLine(PpiLine);
        var station = Station(line, EmptyProgram.Awl, 2);
        station.Memory.V[100] = 0x42;
        await using var rig = await Rig.StartAsync(line);
        var plan = PpiReadPlanner.Plan([PlcAddress.Parse("VB100"), PlcAddress.Parse("SMB6"), PlcAddress.Parse("MW4")]);

        PpiAddressing.TryWrite(PlcAddress.Parse("MW4"), 0x1234, out var write, out _);
        var codes = await rig.Master.WriteAsync(new Station(2), [write!], default).WaitAsync(Rig.Limit);
        var results = await rig.Master.ReadAsync(new Station(2), plan.Requests[0].Items, default).WaitAsync(Rig.Limit);

        codes.Should().Equal(S7ReturnCode.Success);
        Value(plan, results, "VB100").Should().Be("42");
        Value(plan, results, "SMB6").Should().Be(Cpu.CpuIdCode.ToString("X2", System.Globalization.CultureInfo.InvariantCulture));
        Value(plan, results, "MW4").Should().Be("1234");
    }

    [Fact]
    public async Task Read_AnalogSTimerAndCounter_ComeFromTheMemoryTheProgramRunsOn()
    {
        var line = new StlLine(PpiLine);
        var station = Station(line, ValuesProgram.Awl, 2);
        (station.Plc.AreaBytes(MemoryArea.AI)[2], station.Plc.AreaBytes(MemoryArea.AI)[3]) = (0x30, 0x39);
        station.Plc.AreaBytes(MemoryArea.S)[1] = 0x05;
        await using var rig = await Rig.StartAsync(line);
        var plan = PpiReadPlanner.Plan([PlcAddress.Parse("AIW2"), PlcAddress.Parse("AQW0"), PlcAddress.Parse("SB1"), PlcAddress.Parse("T37"), PlcAddress.Parse("C5")]);

        var results = await rig.Master.ReadAsync(new Station(2), plan.Requests[0].Items, default).WaitAsync(Rig.Limit);

        plan.Requests.Should().ContainSingle();
        Value(plan, results, "AIW2").Should().Be("3039", "12345 set in the simulated CPU's analog input");
        Value(plan, results, "AQW0").Should().Be("04D2", "the program's MOVW 1234, AQW0");
        Value(plan, results, "SB1").Should().Be("05");
        Value(plan, results, "T37").Should().Be("00FA", "the program's MOVW 250, T37: the low word of the timer's 4-byte value");
        Value(plan, results, "C5").Should().Be("FFF9", "the program's MOVW -7, C5");
    }

    [Fact]
    public async Task Read_HandlerStationInStopAnswersOverPpi_WhileInRunItIsSilent()
    {
        var line = new StlLine(PpiLine);
        var generated = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = Cpu, Station = 3, BaudRate = Baud });
        generated.Ok.Should().BeTrue(string.Join("; ", generated.Diagnostics));
        var station = Station(line, generated.AwlText, 3);
        station.Memory.M[0] = 0x99;
        // Short and single for the silence (no need to wait long for nothing); the answer in STOP gets the wide time-outs,
        // since its first exchange also pays for the CPU's PPI side starting up on a busy machine.
        await using var rig = await Rig.StartAsync(line, Options with { ReplyTimeout = TimeSpan.FromMilliseconds(150), Retries = 0 });

        var silent = () => rig.Master.ReadAsync(new Station(3), [S7Item.Bytes(S7Area.M, 0, 1)], default).WaitAsync(Rig.Limit);
        (await silent.Should().ThrowAsync<PlcCommunicationException>()).Which.Kind.Should().Be(PlcErrorKind.NoAnswer);

        station.Plc.Stop();
        var answering = rig.MasterWith(Options);
        var results = await answering.ReadAsync(new Station(3), [S7Item.Bytes(S7Area.M, 0, 1)], default).WaitAsync(Rig.Limit);

        results[0].Data.Should().Equal((byte)0x99);
        station.Mode.Should().Be(OperatingMode.Stop);
    }

    private static StlStation Station(StlLine line, string awl, int address)
    {
        StlStation.TryCreate(awl, Cpu, 0, PpiLine, out var station, out var error).Should().BeTrue(error);
        station!.AttachPpi(new PpiSettings(address, Baud));
        line.Attach(station, runProcess: false);
        return station;
    }

    private static string Value(PpiReadPlan plan, IReadOnlyList<S7ItemResult> results, string address)
    {
        var slice = plan.Slices[PlcAddress.Parse(address)];
        return Convert.ToHexString(results[slice.Item].Data.AsSpan(slice.Offset, slice.Length));
    }

    /// <summary>The pty, the host serving the line on one end and the master on the other.</summary>
    private sealed class Rig : IAsyncDisposable
    {
        public static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);

        private readonly SocatPtyPair _pty;
        private readonly CancellationTokenSource _stop = new();
        private readonly SerialPortTransport _panel;
        private readonly SerialPortTransport _plc;
        private Task _host = Task.CompletedTask;

        private Rig(SocatPtyPair pty, SerialPortTransport panel, SerialPortTransport plc, PpiMaster master)
        {
            (_pty, _panel, _plc, Master) = (pty, panel, plc, master);
        }

        public PpiMaster Master { get; }

        /// <summary>A second master on the same port, for a test whose exchanges need different time-outs.</summary>
        public PpiMaster MasterWith(PpiMasterOptions options) => new(_panel, options);

        public static async Task<Rig> StartAsync(StlLine line, PpiMasterOptions? options = null)
        {
            var pty = await SocatPtyPair.StartAsync();
            var plc = new SerialPortTransport(new SerialSettings { PortName = pty.PathB, BaudRate = Baud, Parity = Parity.Even });
            var panel = new SerialPortTransport(new SerialSettings { PortName = pty.PathA, BaudRate = Baud, Parity = Parity.Even });
            await plc.OpenAsync(default);
            await panel.OpenAsync(default);
            var rig = new Rig(pty, panel, plc, new PpiMaster(panel, options ?? Options));
            var host = new SimulatedPlcHost(plc, line, TimeProvider.System);
            rig._host = Task.Run(() => host.RunAsync(rig._stop.Token));
            return rig;
        }

        public async ValueTask DisposeAsync()
        {
            await _stop.CancelAsync();
            try
            {
                await _host;
            }
            catch (OperationCanceledException)
            {
                // The host ends with the cancellation: the normal end of a test.
            }

            await _panel.DisposeAsync();
            await _plc.DisposeAsync();
            _pty.Dispose();
            _stop.Dispose();
        }
    }
}
