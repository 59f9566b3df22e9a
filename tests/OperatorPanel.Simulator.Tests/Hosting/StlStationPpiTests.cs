using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.Simulator.Tests.Hosting;

/// <summary>
/// The simulated S7-200's PPI side on the simulated wire, driven by the panel's <see cref="PpiMaster"/> in the line's
/// own time (<see cref="SimulatedLineTransport"/>): it answers whenever its program does not hold the port in
/// Freeport, once per scan, from the memory the program runs on.
/// </summary>
public sealed class StlStationPpiTests
{
    private static readonly LineSettings PpiLine = new(9600, Parity.Even, 8);
    private static readonly Station Cpu = new(2);

    [Fact]
    public async Task Read_NoHandlerLoaded_ReadsTheCpusMemory()
    {
        var (line, station) = Create(EmptyProgram.Awl);
        station.Memory.V.AsSpan(100, 4).SetBytes([0x12, 0x34, 0x56, 0x78]);
        station.Memory.SM[6].Should().Be(0x20, "a CPU 224 identifies itself in SMB6");
        var master = Master(line, out _);

        var results = await master.ReadAsync(Cpu, [S7Item.Bytes(S7Area.V, 100, 4), S7Item.Bytes(S7Area.SM, 6, 1)], default);

        results.Select(r => Convert.ToHexString(r.Data.AsSpan())).Should().Equal("12345678", "20");
    }

    [Fact]
    public async Task Write_NoHandlerLoaded_LandsInMemoryInTheCommunicationPhase()
    {
        var (line, station) = Create(EmptyProgram.Awl);
        var master = Master(line, out _);
        PpiAddressing.TryWrite(PlcAddress.Parse("MW4"), 0xBEEF, out var word, out _);
        PpiAddressing.TryWrite(PlcAddress.Parse("Q0.3"), 1, out var bit, out _);

        var codes = await master.WriteAsync(Cpu, [word!, bit!], default);

        codes.Should().Equal(S7ReturnCode.Success, S7ReturnCode.Success);
        (station.Memory.M[4], station.Memory.M[5], station.Memory.Q[0]).Should().Be(((byte)0xBE, (byte)0xEF, (byte)0x08));
    }

    [Fact]
    public async Task Read_AcknowledgeComesOneStationDelayAfterTheRequest()
    {
        var (line, _) = Create(EmptyProgram.Awl);
        var transport = new SimulatedLineTransport(line);
        var start = line.Now;
        var request = PpiFrameCodec.Encode(PpiFrame.Variable(2, 0, PpiFunctionCode.FirstRequest, S7JobCodec.Read(1, [S7Item.Bytes(S7Area.M, 0, 1)])));

        await transport.WriteAsync(request, default);
        var buffer = new byte[16];
        var count = await transport.ReadAsync(buffer, TimeSpan.FromMilliseconds(100), default);

        buffer[..count].Should().Equal(0xE5);
        var expected = PpiLine.Bits(11L * (request.Length + 1)) + PpiLine.Bits(11);
        (transport.LastReceivedAt - start).Should().Be(expected, "request, 11 bit times of station delay, then the E5");
    }

    [Fact]
    public async Task Read_LongestJobAtTheSlowestBaud_AcknowledgedWithinTheFirstWait()
    {
        // 19 items fill the 240-byte PDU: a 249-character SD2 telegram, 285 ms on the wire at 9600 baud. The simulated
        // CPU takes it at the baud rate and acknowledges 11 bit times after its last character (288 ms after it was
        // written); the master waits the telegram's own time plus its reply time-out (100 ms here, 300 in opanel).
        var (line, _) = Create(EmptyProgram.Awl);
        var master = Master(line, out _);
        var items = Enumerable.Range(0, 19).Select(i => S7Item.Bytes(S7Area.M, i, 1)).ToArray();
        var request = PpiFrameCodec.Encode(PpiFrame.Variable(2, 0, PpiFunctionCode.FirstRequest, S7JobCodec.Read(1, items)));

        var results = await master.ReadAsync(Cpu, items, default);

        request.Length.Should().Be(249);
        results.Should().HaveCount(19).And.OnlyContain(r => r.Succeeded);
        master.Repeats.Should().Be(0, "the acknowledge came within the first wait, so the job was not sent again");
        (master.Options.Characters(249) + master.Options.ReplyTimeout).Should().BeGreaterThan(PpiLine.Bits((11L * 250) + 11));
    }

    [Fact]
    public async Task Read_LongScans_AnswerWaitsForTheCommunicationPhase()
    {
        var (line, station) = Create(EmptyProgram.Awl);
        station.Plc.UserProgramTime = TimeSpan.FromMilliseconds(200);
        var scans = station.Plc.Scans;
        while (station.Plc.Scans < scans + 2)
        {
            line.RunUntil(line.Now + TimeSpan.FromMilliseconds(0.1));
        }

        // A 200 ms scan has just begun: its communication phase comes after 200 ms of program.
        var start = line.Now;
        var master = Master(line, out _);

        await master.ReadAsync(Cpu, [S7Item.Bytes(S7Area.M, 0, 1)], default);

        master.EmptyPolls.Should().BeGreaterThan(5, "each poll before the communication phase is answered E5");
        (line.Now - start).Should().BeGreaterThan(TimeSpan.FromMilliseconds(200)).And.BeLessThan(TimeSpan.FromMilliseconds(260));
    }

    [Fact]
    public async Task Read_HandlerHoldsThePortInFreeport_NoPpiAnswer()
    {
        var (line, _) = Create(HandlerText(2));
        var master = Master(line, out _);

        var act = () => master.ReadAsync(Cpu, [S7Item.Bytes(S7Area.M, 0, 1)], default);

        (await act.Should().ThrowAsync<PlcCommunicationException>()).Which.Kind.Should().Be(PlcErrorKind.NoAnswer);
    }

    [Fact]
    public async Task Read_HandlerLoadedButCpuInStop_AnswersOverPpi()
    {
        var (line, station) = Create(HandlerText(2));
        station.Plc.Stop();
        station.Memory.M[7] = 0x5A;
        var master = Master(line, out _);

        var results = await master.ReadAsync(Cpu, [S7Item.Bytes(S7Area.M, 7, 1)], default);

        results[0].Data.Should().Equal((byte)0x5A);
        station.Mode.Should().Be(OperatingMode.Stop);
    }

    [Fact]
    public async Task Read_HandlerLoadedAndSwitchAtTerm_AnswersOverPpi()
    {
        var (line, station) = Create(HandlerText(2));
        station.Plc.ModeSwitch = ModeSwitch.Term;
        line.RunUntil(line.Now + TimeSpan.FromMilliseconds(50));
        var master = Master(line, out _);

        var results = await master.ReadAsync(Cpu, [S7Item.Bit(S7Area.SM, 0, 7)], default);

        results[0].Data.Should().Equal([(byte)0], "SM0.7 is off at TERM");
        station.Mode.Should().Be(OperatingMode.Run, "TERM leaves the CPU running; the handler gave the port back");
    }

    [Fact]
    public async Task Control_StopThenRun_PutsTheSimulatedCpuInStopAndBack()
    {
        var (line, station) = Create(EmptyProgram.Awl);
        var master = Master(line, out var transport);

        await master.ExchangeAsync(Cpu, S7JobCodec.Stop(9), default);
        station.Mode.Should().Be(OperatingMode.Stop);
        await master.ExchangeAsync(Cpu, S7JobCodec.Run(10), default);

        station.Mode.Should().Be(OperatingMode.Run);
        transport.IsOpen.Should().BeFalse();
    }

    private static (StlLine Line, StlStation Station) Create(string awl)
    {
        var line = new StlLine(PpiLine);
        StlStation.TryCreate(awl, StlStations.Cpu224, 0, PpiLine, out var station, out var error).Should().BeTrue(error);
        station!.AttachPpi(new PpiSettings(2, 9600));
        line.Attach(station, runProcess: false);
        line.RunUntil(TimeSpan.FromMilliseconds(50));
        return (line, station);
    }

    private static PpiMaster Master(StlLine line, out SimulatedLineTransport transport)
    {
        transport = new SimulatedLineTransport(line);
        return new PpiMaster(transport, PpiMasterOptions.ForBaud(9600), transport.Clock);
    }

    private static string HandlerText(int station)
    {
        using var stream = typeof(StlStations).Assembly.GetManifestResourceStream($"Handler224Station{station}.awl")!;
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }
}
