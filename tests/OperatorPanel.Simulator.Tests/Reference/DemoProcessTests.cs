using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

public sealed class DemoProcessTests
{
    private static (ReferencePlc Plc, DemoProcess Process) Line()
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224)));
        return (plc, new DemoProcess(plc));
    }

    [Fact]
    public void Advance_SameStepsTwice_GivesTheSameMemory()
    {
        var (a, runA) = Line();
        var (b, runB) = Line();

        runA.Advance(TimeSpan.FromSeconds(95));
        for (var i = 0; i < 95; i++)
        {
            runB.Advance(TimeSpan.FromMilliseconds(999));
        }

        runB.Advance(TimeSpan.FromMilliseconds(95));
        b.Memory.I.Should().Equal(a.Memory.I);
        b.Memory.Q.Should().Equal(a.Memory.Q);
        b.Memory.M.Should().Equal(a.Memory.M);
        b.Memory.V.Should().Equal(a.Memory.V);
        b.Memory.SM.Should().Equal(a.Memory.SM);
    }

    [Fact]
    public void Advance_TwentySeconds_CountsABottlePerSecondAndRunsTheConveyor()
    {
        var (plc, run) = Line();

        run.Advance(TimeSpan.FromSeconds(19.5));

        plc.Memory.ReadDoubleWord(ProtocolArea.V, 100).Should().Be(20); // 0.02 s, 1 s, 2 s ... 19 s
        BitConverter.UInt32BitsToSingle(plc.Memory.ReadDoubleWord(ProtocolArea.V, 120)).Should().Be(10f);
        plc.Memory.GetBit(ProtocolArea.Q, 0, 0).Should().BeTrue();
        plc.Memory.ReadWord(ProtocolArea.V, 104).Should().Be(60);
    }

    [Fact]
    public void Advance_GuardDoorOpen_RaisesM20AndStopsTheConveyor()
    {
        var (plc, run) = Line();

        run.Advance(TimeSpan.FromSeconds(21));

        plc.Memory.GetBit(ProtocolArea.M, 2, 0).Should().BeTrue();
        plc.Memory.GetBit(ProtocolArea.Q, 0, 0).Should().BeFalse();
        plc.Memory.V[110].Should().Be(2);
        run.Advance(TimeSpan.FromSeconds(3));
        plc.Memory.GetBit(ProtocolArea.M, 2, 0).Should().BeFalse();
    }

    [Fact]
    public void Advance_OneMinute_EveryAlarmBitComesAndGoes()
    {
        var (plc, run) = Line();
        var seenOn = 0;
        var seenOff = 0;

        for (var i = 0; i < 600; i++)
        {
            run.Advance(TimeSpan.FromMilliseconds(100));
            seenOn |= plc.Memory.M[2];
            seenOff |= ~plc.Memory.M[2] & 0xFF;
        }

        seenOn.Should().Be(0xFF);
        seenOff.Should().Be(0xFF);
    }

    [Fact]
    public void Advance_OutputWrittenByPanel_KeepsThePanelValue()
    {
        var (plc, run) = Line();
        plc.HandleFrame(RequestCodec.Encode(new WriteBitRequest(new Station(1), 1, ProtocolArea.Q, 0, 7, true)));

        run.Advance(TimeSpan.FromSeconds(2));

        plc.Memory.GetBit(ProtocolArea.Q, 0, 7).Should().BeTrue();
        plc.ReleaseOutputs();
        run.Advance(TimeSpan.FromMilliseconds(10));
        plc.Memory.GetBit(ProtocolArea.Q, 0, 7).Should().BeFalse();
    }

    [Fact]
    public void Advance_Scans_MaintainScanTimeWords()
    {
        var (plc, run) = Line();

        run.Advance(TimeSpan.FromSeconds(1));

        plc.Memory.ReadWord(ProtocolArea.SM, 24).Should().Be(3);
        plc.Memory.ReadWord(ProtocolArea.SM, 26).Should().Be(6);
        plc.Memory.ReadWord(ProtocolArea.SM, 22).Should().BeInRange(3, 6);
    }
}
