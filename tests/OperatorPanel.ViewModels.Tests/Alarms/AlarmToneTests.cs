using System.Buffers.Binary;
using OperatorPanel.Core.Alarms;
using OperatorPanel.ViewModels.Alarms;

namespace OperatorPanel.ViewModels.Tests.Alarms;

/// <summary>The alarm tones are playable WAV files of the length they claim.</summary>
public sealed class AlarmToneTests
{
    [Theory]
    [InlineData(AlarmClass.Fault, 600)]
    [InlineData(AlarmClass.Warning, 480)]
    [InlineData(AlarmClass.Information, 420)]
    public void Wave_EachClass_IsPcmMonoWavOfItsLength(AlarmClass alarmClass, int milliseconds)
    {
        var wave = AlarmTone.Wave(alarmClass);

        System.Text.Encoding.ASCII.GetString(wave, 0, 4).Should().Be("RIFF");
        System.Text.Encoding.ASCII.GetString(wave, 8, 8).Should().Be("WAVEfmt ");
        BinaryPrimitives.ReadInt16LittleEndian(wave.AsSpan(20)).Should().Be(1, "PCM");
        BinaryPrimitives.ReadInt16LittleEndian(wave.AsSpan(22)).Should().Be(1, "mono");
        BinaryPrimitives.ReadInt32LittleEndian(wave.AsSpan(40)).Should().Be(wave.Length - 44);
        AlarmTone.Length(alarmClass).TotalMilliseconds.Should().BeApproximately(milliseconds, 1);
    }

    [Fact]
    public void Wave_StartsAndEndsSilent_SoTheSpeakerDoesNotClick()
    {
        var wave = AlarmTone.Wave(AlarmClass.Fault);

        BinaryPrimitives.ReadInt16LittleEndian(wave.AsSpan(44)).Should().Be(0);
        BinaryPrimitives.ReadInt16LittleEndian(wave.AsSpan(wave.Length - 2)).Should().Be(0);
    }
}
