using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Ppi;
using OperatorPanel.Simulator.Tests.Hosting;

namespace OperatorPanel.Simulator.Tests.Stl.Ppi;

public sealed class StlPpiMemoryTests
{
    private readonly StlPlc _plc = StlTestPrograms.Plc("LD SM0.0\nTON T37, +30000\nLD SM0.1\nLD SM0.0\nNOT\nCTU C3, +1");
    private readonly StlPpiMemory _memory;

    public StlPpiMemoryTests() => _memory = new StlPpiMemory(_plc);

    [Fact]
    public void Read_EveryByteArea_ComesFromTheProgramsMemory()
    {
        _plc.AreaBytes(Core.Addressing.MemoryArea.S)[1] = 0x44;
        _plc.AreaBytes(Core.Addressing.MemoryArea.AI)[2] = 0x7D;

        Data(_memory.Read(S7Item.Bytes(S7Area.S, 1, 1))).Should().Be("44");
        Data(_memory.Read(S7Item.Words(S7Area.AI, 2, 1))).Should().Be("7D00");
    }

    [Fact]
    public void Read_BeyondTheArea_IsAddressOutOfRange()
    {
        _memory.Read(S7Item.Bytes(S7Area.V, 8190, 4)).Code.Should().Be(S7ReturnCode.AddressOutOfRange, "a CPU 224 has VB0-VB8191");
        _memory.Read(S7Item.Bytes(S7Area.M, 31, 1)).Code.Should().Be(S7ReturnCode.Success);
    }

    [Fact]
    public void Read_DataBlockOtherThanOne_IsAccessDenied()
    {
        var db2 = S7Item.Bytes(S7Area.V, 0, 1) with { DataBlock = 2 };

        _memory.Read(db2).Code.Should().Be(S7ReturnCode.AccessDenied, "libnodave: the 200 family answers 3 for a data block it lacks");
    }

    [Fact]
    public void Read_BitItemOfTwoBits_IsAccessDenied()
    {
        var twoBits = S7Item.Bit(S7Area.M, 0, 1) with { Count = 2 };

        _memory.Read(twoBits).Code.Should().Be(S7ReturnCode.AccessDenied);
    }

    [Fact]
    public void Read_TimerAndCounter_FiveBytesWithTheBitInBit1AndTheValueLast()
    {
        _plc.RunUntil(TimeSpan.FromMilliseconds(2500));

        var timer = _memory.Read(S7Item.Timers(37, 1));
        var counter = _memory.Read(S7Item.Counters(3, 1));

        timer.DataSize.Should().Be(S7DataSize.OctetString);
        timer.Data[0].Should().Be(0, "T37 (100 ms) has not reached 30000 yet");
        ((timer.Data[3] << 8) | timer.Data[4]).Should().Be(_plc.TimerCurrentValue(37)).And.BeGreaterThan(20);
        Data(counter).Should().Be("0200000001", "C3 counted the first scan's rising edge and reached its preset 1");
    }

    [Fact]
    public void Write_ReadOnlyPlaces_AreAccessDenied()
    {
        _memory.Write(S7WriteItem.Of(S7Item.Bytes(S7Area.SM, 29, 1), [1])).Should().Be(S7ReturnCode.AccessDenied);
        _memory.Write(S7WriteItem.Of(S7Item.Words(S7Area.AI, 0, 1), [1, 2])).Should().Be(S7ReturnCode.AccessDenied);
        _memory.Write(S7WriteItem.Of(S7Item.Timers(1, 1), [0, 0, 0, 0, 1])).Should().Be(S7ReturnCode.AccessDenied);
        _memory.Write(S7WriteItem.Of(S7Item.Bytes(S7Area.SM, 30, 1), [9])).Should().Be(S7ReturnCode.Success);
    }

    [Fact]
    public void Write_Bit_ChangesOnlyThatBit()
    {
        _plc.Memory.V[10] = 0b1010_0000;

        _memory.Write(S7WriteItem.Of(S7Item.Bit(S7Area.V, 10, 0), [1])).Should().Be(S7ReturnCode.Success);
        _memory.Write(S7WriteItem.Of(S7Item.Bit(S7Area.V, 10, 7), [0])).Should().Be(S7ReturnCode.Success);

        _plc.Memory.V[10].Should().Be(0b0010_0001);
    }

    private static string Data(S7ItemResult result)
    {
        result.Code.Should().Be(S7ReturnCode.Success);
        return Convert.ToHexString(result.Data.AsSpan());
    }
}
