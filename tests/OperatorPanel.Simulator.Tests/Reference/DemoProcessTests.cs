using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Reference;

/// <summary>The demo filler against the addresses and alarm texts of samples/bottling-line.opproj.</summary>
public sealed class DemoProcessTests
{
    private static readonly TimeSpan Step = TimeSpan.FromMilliseconds(100);

    [Fact]
    public void Advance_SameTimeInDifferentSteps_GivesTheSameMemory()
    {
        var (a, runA) = Line();
        var (b, runB) = Line();

        runA.Advance(TimeSpan.FromSeconds(250));
        for (var i = 0; i < 250; i++)
        {
            runB.Advance(TimeSpan.FromMilliseconds(999));
        }

        runB.Advance(TimeSpan.FromMilliseconds(250));
        runB.Elapsed.Should().Be(runA.Elapsed);
        b.Memory.I.Should().Equal(a.Memory.I);
        b.Memory.Q.Should().Equal(a.Memory.Q);
        b.Memory.M.Should().Equal(a.Memory.M);
        b.Memory.V.Should().Equal(a.Memory.V);
        b.Memory.SM.Should().Equal(a.Memory.SM);
    }

    [Fact]
    public void Advance_TwoSeconds_ShowsARunningLineWithRecipeAndTheTankRefilling()
    {
        var (plc, run) = Line();

        run.Advance(TimeSpan.FromSeconds(2));

        var m = plc.Memory;
        (I(m, 0, 0), I(m, 0, 2), I(m, 0, 4)).Should().Be((true, true, true)); // e-stop chain and Stop (NC) healthy, AUTO
        (Q(m, 0, 0), Q(m, 0, 5), Q(m, 0, 6)).Should().Be((true, true, false)); // conveyor, green lamp, no fault lamp
        m.ReadDoubleWord(ProtocolArea.V, 100).Should().BeGreaterThanOrEqualTo(1);
        m.ReadWord(ProtocolArea.V, 104).Should().Be(800);
        m.V[110].Should().Be(3);
        BitConverter.UInt32BitsToSingle(m.ReadDoubleWord(ProtocolArea.V, 120)).Should().Be(500f);
        Encoding.ASCII.GetString(m.V, 130, 4).Should().Be("B042");
        m.ReadWord(ProtocolArea.V, 150).Should().BeInRange(150, 200); // shift start: tank low, pump on
        (I(m, 1, 1), Q(m, 0, 4), Q(m, 0, 7), Alarm(m, 2)).Should().Be((true, true, true, true));
        m.V[160].Should().Be(3); // FaultCode: M2.2 is bit 2, code 3
    }

    [Fact]
    public void Advance_WhileRunning_CountsAboutFortyBottlesAMinute()
    {
        var (plc, run) = Line();
        run.Advance(TimeSpan.FromSeconds(10));
        var before = plc.Memory.ReadDoubleWord(ProtocolArea.V, 100);

        run.Advance(TimeSpan.FromSeconds(15));

        (plc.Memory.ReadDoubleWord(ProtocolArea.V, 100) - before).Should().BeInRange(9, 12);
        plc.Memory.ReadWord(ProtocolArea.V, 140).Should().BeInRange(35, 50);
    }

    [Fact]
    public void Advance_FillSequence_CyclesThroughItsStepsWithValveAndProbe()
    {
        var (plc, run) = Line();
        var steps = new HashSet<ushort>();
        var seen = (Stop: false, Head: false, Valve: false, Full: false, Filling: false);

        for (var i = 0; i < 300; i++)
        {
            run.Advance(DemoProcess.ScanPeriod);
            var m = plc.Memory;
            steps.Add((ushort)(m.ReadWord(ProtocolArea.M, 10) & 0x1F));
            seen = (seen.Stop | Q(m, 0, 2), seen.Head | Q(m, 0, 3), seen.Valve | Q(m, 0, 1), seen.Full | I(m, 1, 2), seen.Filling | m.GetBit(ProtocolArea.M, 0, 0));
        }

        steps.Should().BeEquivalentTo(new ushort[] { 0x01, 0x02, 0x04, 0x08, 0x10 }); // one step bit at a time
        seen.Should().Be((true, true, true, true, true));
    }

    [Theory]
    [InlineData(DemoScript.AirDipAt, 5)] //      M2.5 Compressed air pressure low
    [InlineData(DemoScript.GuardDoorAt, 3)] //   M2.3 Guard door opened during operation
    [InlineData(DemoScript.JamAt, 1)] //         M2.1 Bottle jam at infeed
    [InlineData(DemoScript.MotorTripAt, 4)] //   M2.4 Conveyor motor overload
    [InlineData(DemoScript.EStopAt, 0)] //       M2.0 Emergency stop pressed
    public void Advance_ScriptedFault_RaisesItsAlarmStopsTheLineAndRecovers(long atMs, int alarmBit)
    {
        var (plc, run) = Line();
        run.Advance(TimeSpan.FromMilliseconds(atMs + 3_000));
        var m = plc.Memory;
        var count = m.ReadDoubleWord(ProtocolArea.V, 100);

        Alarm(m, alarmBit).Should().BeTrue();
        m.V[160].Should().Be((byte)(alarmBit + 1));
        (Q(m, 0, 0), Q(m, 0, 5), Q(m, 0, 6), Q(m, 1, 0)).Should().Be((false, false, true, true)); // stopped, fault lamp, horn
        run.Advance(TimeSpan.FromSeconds(1));
        m.ReadDoubleWord(ProtocolArea.V, 100).Should().Be(count);

        run.Advance(TimeSpan.FromSeconds(20));
        Alarm(m, alarmBit).Should().BeFalse();
        (Q(m, 0, 0), Q(m, 0, 5), Q(m, 0, 6)).Should().Be((true, true, false));
        m.ReadDoubleWord(ProtocolArea.V, 100).Should().BeGreaterThan(count);
    }

    [Fact]
    public void Advance_EmergencyStop_OpensTheChainOnlyForItsEpisode()
    {
        var (plc, run) = Line();
        var open = 0;

        for (var i = 0; i < 3_000; i++)
        {
            run.Advance(Step);
            open += I(plc.Memory, 0, 0) ? 0 : 1;
        }

        open.Should().Be(40); // 4 s of the first five minutes
    }

    [Fact]
    public void Advance_TenMinutes_EveryAlarmBitRisesAndFallsAgain()
    {
        var (plc, run) = Line();
        var rises = new int[8];
        var falls = new int[8];
        byte last = 0;

        for (var i = 0; i < 6_000; i++)
        {
            run.Advance(Step);
            var now = plc.Memory.M[2];
            for (var bit = 0; bit < 8; bit++)
            {
                rises[bit] += (now & ~last & (1 << bit)) != 0 ? 1 : 0;
                falls[bit] += (~now & last & (1 << bit)) != 0 ? 1 : 0;
            }

            last = now;
        }

        rises.Should().OnlyContain(n => n >= 1);
        falls.Should().OnlyContain(n => n >= 1);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 144).Should().Be((uint)rises[6]); // each slow fill rejects its bottle
    }

    [Fact]
    public void Advance_TenMinutes_TankStaysInRangeFollowsItsSwitchesAndThePumpCycles()
    {
        var (plc, run) = Line();
        var pumpSwitches = 0;
        var pumpWas = false;

        for (var i = 0; i < 6_000; i++)
        {
            run.Advance(Step);
            var m = plc.Memory;
            var level = (short)m.ReadWord(ProtocolArea.V, 150);
            level.Should().BeInRange(0, 1000);
            if (I(m, 1, 0))
            {
                level.Should().BeGreaterThanOrEqualTo(850);
            }

            if (I(m, 1, 1))
            {
                level.Should().BeLessThanOrEqualTo(200);
            }

            pumpSwitches += Q(m, 0, 4) != pumpWas ? 1 : 0;
            pumpWas = Q(m, 0, 4);
        }

        pumpSwitches.Should().BeGreaterThanOrEqualTo(3); // on at the start, off at the high switch, on again at the low one
    }

    [Fact]
    public void Advance_PumpOffWhileFilling_LowersTheTankLevel()
    {
        var (plc, run) = Line();
        run.Advance(TimeSpan.FromSeconds(150));
        var before = plc.Memory.ReadWord(ProtocolArea.V, 150);

        run.Advance(TimeSpan.FromSeconds(40));

        Q(plc.Memory, 0, 4).Should().BeFalse();
        plc.Memory.ReadWord(ProtocolArea.V, 150).Should().BeLessThan((ushort)(before - 50));
    }

    [Fact]
    public void Advance_OutputWrittenByPanel_KeepsThePanelValueUntilReleased()
    {
        var (plc, run) = Line();
        plc.HandleFrame(RequestCodec.Encode(new WriteBitRequest(new Station(1), 1, ProtocolArea.Q, 1, 1, true)));
        plc.HandleFrame(RequestCodec.Encode(new WriteBitRequest(new Station(1), 2, ProtocolArea.Q, 0, 0, false)));

        run.Advance(TimeSpan.FromSeconds(5));

        (Q(plc.Memory, 1, 1), Q(plc.Memory, 0, 0)).Should().Be((true, false));
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 100).Should().Be(0); // the conveyor stood still: no bottle reached the outfeed
        plc.ReleaseOutputs();
        run.Advance(TimeSpan.FromSeconds(5));
        (Q(plc.Memory, 1, 1), Q(plc.Memory, 0, 0)).Should().Be((false, true));
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 100).Should().BeGreaterThan(0);
    }

    [Fact]
    public void Advance_PlcInStop_FreezesOutputsAndTags()
    {
        var (plc, run) = Line();
        run.Advance(TimeSpan.FromSeconds(5));
        plc.Mode = OperatingMode.Stop;
        var outputs = plc.Memory.Q.ToArray();
        var count = plc.Memory.ReadDoubleWord(ProtocolArea.V, 100);

        run.Advance(TimeSpan.FromSeconds(10));

        plc.Memory.Q.Should().Equal(outputs);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 100).Should().Be(count);
        plc.Mode = OperatingMode.Run;
        run.Advance(TimeSpan.FromSeconds(10));
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 100).Should().BeGreaterThan(count);
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

    private static (ReferencePlc Plc, DemoProcess Process) Line()
    {
        var plc = new ReferencePlc(new HandlerConfig(new Station(1), CpuProfiles.For(CpuModel.Cpu224)));
        return (plc, new DemoProcess(plc));
    }

    private static bool I(PlcMemory m, int offset, int bit) => m.GetBit(ProtocolArea.I, offset, bit);

    private static bool Q(PlcMemory m, int offset, int bit) => m.GetBit(ProtocolArea.Q, offset, bit);

    private static bool Alarm(PlcMemory m, int bit) => m.GetBit(ProtocolArea.M, 2, bit);
}
