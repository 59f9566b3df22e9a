using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Tests.Addressing;

public sealed class AddressRulesTests
{
    /// <summary>
    /// The last byte of each area, written out from the manuals (docs/cpu-profiles.md) rather than read from CpuProfiles,
    /// so a wrong figure in the catalogue fails here. -1: the CPU has no such area.
    /// </summary>
    public static TheoryData<CpuModel, CpuRevision, MemoryArea, int> LastBytes()
    {
        var data = new TheoryData<CpuModel, CpuRevision, MemoryArea, int>();
        (CpuModel Model, CpuRevision Revision, int V, int Sm, int Analog)[] cpus =
        [
            (CpuModel.Cpu221, CpuRevision.Early, 2047, 179, -1),
            (CpuModel.Cpu221, CpuRevision.Current, 2047, 179, -1),
            (CpuModel.Cpu222, CpuRevision.Early, 2047, 299, 31),
            (CpuModel.Cpu222, CpuRevision.Current, 2047, 299, 31),
            (CpuModel.Cpu224, CpuRevision.Early, 5119, 549, 31),
            (CpuModel.Cpu224, CpuRevision.Current, 8191, 549, 63),
            (CpuModel.Cpu224XP, CpuRevision.Current, 10239, 549, 63),
            (CpuModel.Cpu226, CpuRevision.Current, 10239, 549, 63),
        ];
        foreach (var cpu in cpus)
        {
            data.Add(cpu.Model, cpu.Revision, MemoryArea.I, 15);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.Q, 15);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.M, 31);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.S, 31);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.V, cpu.V);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.SM, cpu.Sm);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.AI, cpu.Analog);
            data.Add(cpu.Model, cpu.Revision, MemoryArea.AQ, cpu.Analog);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(LastBytes))]
    public void Check_AtTheEdgesOfEveryArea_AcceptsInsideAndRefusesOnePast(CpuModel model, CpuRevision revision, MemoryArea area, int lastByte)
    {
        var cpu = CpuProfiles.For(model, revision);
        if (lastByte < 0)
        {
            var absent = AddressRules.Check(PlcAddress.ForBytes(area, 0, AccessWidth.Word), cpu);
            absent!.Kind.Should().Be(AddressErrorKind.AreaNotOnCpu);
            return;
        }

        if (area is MemoryArea.AI or MemoryArea.AQ)
        {
            AddressRules.Check(PlcAddress.ForBytes(area, lastByte - 1, AccessWidth.Word), cpu).Should().BeNull();
            AddressRules.Check(PlcAddress.ForBytes(area, lastByte + 1, AccessWidth.Word), cpu)!.Kind.Should().Be(AddressErrorKind.OutOfRange);
            return;
        }

        AddressRules.Check(PlcAddress.ForBit(area, 0, 0), cpu).Should().BeNull();
        AddressRules.Check(PlcAddress.ForBit(area, lastByte, 7), cpu).Should().BeNull();
        AddressRules.Check(PlcAddress.ForBytes(area, lastByte, AccessWidth.Byte), cpu).Should().BeNull();
        AddressRules.Check(PlcAddress.ForBytes(area, lastByte - 1, AccessWidth.Word), cpu).Should().BeNull();
        AddressRules.Check(PlcAddress.ForBytes(area, lastByte - 3, AccessWidth.DoubleWord), cpu).Should().BeNull();

        AddressRules.Check(PlcAddress.ForBit(area, lastByte + 1, 0), cpu)!.Kind.Should().Be(AddressErrorKind.OutOfRange);
        AddressRules.Check(PlcAddress.ForBytes(area, lastByte + 1, AccessWidth.Byte), cpu)!.Kind.Should().Be(AddressErrorKind.OutOfRange);
        AddressRules.Check(PlcAddress.ForBytes(area, lastByte, AccessWidth.Word), cpu)!.Kind.Should().Be(AddressErrorKind.OutOfRange);
        AddressRules.Check(PlcAddress.ForBytes(area, lastByte - 2, AccessWidth.DoubleWord), cpu)!.Kind.Should().Be(AddressErrorKind.OutOfRange);
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, "VD2046", "VD2046 ends at VB2049, past the last V byte VB2047 of CPU 221")]
    [InlineData(CpuModel.Cpu221, "VB2048", "VB2048 is past the last V byte VB2047 of CPU 221")]
    [InlineData(CpuModel.Cpu221, "V2048.0", "V2048.0 is past the last V byte VB2047 of CPU 221")]
    [InlineData(CpuModel.Cpu224, "VW8191", "VW8191 ends at VB8192, past the last V byte VB8191 of CPU 224")]
    [InlineData(CpuModel.Cpu226, "SMD548", "SMD548 ends at SMB551, past the last SM byte SMB549 of CPU 226")]
    [InlineData(CpuModel.Cpu224, "QB16", "QB16 is past the last output byte QB15 of CPU 224")]
    [InlineData(CpuModel.Cpu224, "I16.0", "I16.0 is past the last input byte IB15 of CPU 224")]
    [InlineData(CpuModel.Cpu222, "AIW32", "AIW32 is past the last analog input word AIW30 of CPU 222")]
    [InlineData(CpuModel.Cpu221, "AIW0", "AIW0: CPU 221 has no analog inputs (AIW)")]
    [InlineData(CpuModel.Cpu221, "AQW0", "AQW0: CPU 221 has no analog outputs (AQW)")]
    public void Check_OutsideTheCpu_SaysWhatAndWhy(CpuModel model, string text, string message)
    {
        var error = AddressRules.Check(PlcAddress.Parse(text), CpuProfiles.For(model));

        error!.Message.Should().Be(message);
    }

    [Theory]
    [InlineData("I0.0", "inputs are read from the field; the panel never writes them")]
    [InlineData("IB3", "inputs are read from the field")]
    [InlineData("SMB29", "SMB0-SMB29 are read-only system status bytes")]
    [InlineData("SMW28", "SMB0-SMB29 are read-only")]
    [InlineData("SM0.7", "SMB0-SMB29 are read-only")]
    [InlineData("AIW0", "analog inputs are read-only")]
    [InlineData("AQW0", "the Freeport link writes only Q, M and V")]
    [InlineData("S0.0", "the Freeport link writes only Q, M and V")]
    [InlineData("SMB30", "the Freeport handler does not serve SM (no S7-200 manual page found says a pointer reaches it); write a V byte")]
    [InlineData("SMD546", "the Freeport handler does not serve SM")]
    public void Check_WriteToReadOnlyPlace_IsRefused(string text, string messagePart)
    {
        var error = AddressRules.Check(PlcAddress.Parse(text), CpuProfiles.For(CpuModel.Cpu224), AddressUse.Write);

        error!.Kind.Should().Be(AddressErrorKind.NotWritable);
        error.Message.Should().Contain(messagePart);
    }

    [Theory]
    [InlineData("Q0.0")]
    [InlineData("QB15")]
    [InlineData("M31.7")]
    [InlineData("MD28")]
    [InlineData("VW8190")]
    public void Check_WriteToWritablePlace_IsAccepted(string text)
    {
        AddressRules.Check(PlcAddress.Parse(text), CpuProfiles.For(CpuModel.Cpu224), AddressUse.Write).Should().BeNull();
    }

    [Fact]
    public void Check_ReadOfReadOnlyPlace_IsAccepted()
    {
        AddressRules.Check(PlcAddress.Parse("IB0"), CpuProfiles.For(CpuModel.Cpu224)).Should().BeNull();
        AddressRules.Check(PlcAddress.Parse("SMW22"), CpuProfiles.For(CpuModel.Cpu224)).Should().BeNull();
    }
}
