using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Tests.Stl.Freeport;

public sealed class LineSettingsTests
{
    [Theory]
    [InlineData(0x09, CpuRevision.Current, 9600, Parity.None, 8)]
    [InlineData(0x49, CpuRevision.Current, 9600, Parity.Even, 8)]
    [InlineData(0xC9, CpuRevision.Current, 9600, Parity.Odd, 8)]
    [InlineData(0x89, CpuRevision.Current, 9600, Parity.None, 8)]
    [InlineData(0x29, CpuRevision.Current, 9600, Parity.None, 7)]
    [InlineData(0x01, CpuRevision.Current, 38400, Parity.None, 8)]
    [InlineData(0x19, CpuRevision.Current, 115200, Parity.None, 8)]
    [InlineData(0x1D, CpuRevision.Current, 57600, Parity.None, 8)]
    [InlineData(0x19, CpuRevision.Early, 600, Parity.None, 8)]
    [InlineData(0x1D, CpuRevision.Early, 300, Parity.None, 8)]
    public void TryFromControlByte_FreeportCodes_DecodeWithTheRevisionsBaudCodes(
        int control, CpuRevision revision, int baud, Parity parity, int dataBits)
    {
        LineSettings.TryFromControlByte((byte)control, CpuProfiles.For(CpuModel.Cpu224, revision), out var line)
            .Should().BeTrue();

        line.Should().Be(new LineSettings(baud, parity, dataBits));
    }

    [Theory]
    [InlineData(0x08)]
    [InlineData(0x0A)]
    [InlineData(0x0B)]
    public void TryFromControlByte_PpiModes_AreNotFreeport(int control) =>
        LineSettings.TryFromControlByte((byte)control, CpuProfiles.For(CpuModel.Cpu224), out _).Should().BeFalse();

    [Theory]
    [InlineData(9600, Parity.None, 8, 10_417)]
    [InlineData(9600, Parity.Even, 8, 11_458)]
    [InlineData(1200, Parity.Odd, 7, 83_333)]
    [InlineData(115200, Parity.None, 8, 868)]
    public void CharacterTime_IsBitsPerCharacterOverBaud(int baud, Parity parity, int dataBits, long ticks) =>
        new LineSettings(baud, parity, dataBits).CharacterTime.Should().Be(TimeSpan.FromTicks(ticks));

    [Fact]
    public void From_SerialSettings_TakesBaudParityAndDataBits() =>
        LineSettings.From(new SerialSettings { PortName = "COM1", BaudRate = 19200, Parity = Parity.Even })
            .ToString().Should().Be("19200 8E1");
}
