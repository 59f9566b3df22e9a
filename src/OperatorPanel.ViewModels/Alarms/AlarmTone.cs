using System.Buffers.Binary;
using OperatorPanel.Core.Alarms;

namespace OperatorPanel.ViewModels.Alarms;

/// <summary>
/// The alarm tones as WAV files (16-bit mono PCM, 22050 Hz), made here rather than taken from the Windows sound scheme,
/// which a PC may have set to "No sounds": a fault is a fast two-tone (880/660 Hz) like a horn, a warning two beeps of
/// 700 Hz, a notice one falling chime. Each tone fades in and out over 5 ms so the speaker does not click.
/// </summary>
public static class AlarmTone
{
    public const int SampleRate = 22050;

    public static byte[] Wave(AlarmClass alarmClass)
    {
        var notes = alarmClass switch
        {
            AlarmClass.Fault => [(880.0, 150), (660.0, 150), (880.0, 150), (660.0, 150)],
            AlarmClass.Warning => [(700.0, 180), (0.0, 120), (700.0, 180)],
            AlarmClass.Information => new[] { (660.0, 160), (523.0, 260) },
        };
        var samples = new List<short>();
        foreach (var (hz, ms) in notes)
        {
            var count = SampleRate * ms / 1000;
            var fade = SampleRate * 5 / 1000;
            for (var i = 0; i < count; i++)
            {
                var envelope = Math.Min(1.0, Math.Min(i, count - 1 - i) / (double)fade);
                samples.Add((short)(hz == 0 ? 0 : 0.5 * short.MaxValue * envelope * Math.Sin(2 * Math.PI * hz * i / SampleRate)));
            }
        }

        return Riff(samples);
    }

    /// <summary>How long <see cref="Wave"/> of <paramref name="alarmClass"/> plays.</summary>
    public static TimeSpan Length(AlarmClass alarmClass) => TimeSpan.FromSeconds((Wave(alarmClass).Length - 44) / 2.0 / SampleRate);

    private static byte[] Riff(List<short> samples)
    {
        var data = samples.Count * 2;
        var wave = new byte[44 + data];
        var span = wave.AsSpan();
        "RIFF"u8.CopyTo(span);
        BinaryPrimitives.WriteInt32LittleEndian(span[4..], 36 + data);
        "WAVEfmt "u8.CopyTo(span[8..]);
        BinaryPrimitives.WriteInt32LittleEndian(span[16..], 16); // PCM format chunk
        BinaryPrimitives.WriteInt16LittleEndian(span[20..], 1); // PCM
        BinaryPrimitives.WriteInt16LittleEndian(span[22..], 1); // mono
        BinaryPrimitives.WriteInt32LittleEndian(span[24..], SampleRate);
        BinaryPrimitives.WriteInt32LittleEndian(span[28..], SampleRate * 2); // bytes per second
        BinaryPrimitives.WriteInt16LittleEndian(span[32..], 2); // block align
        BinaryPrimitives.WriteInt16LittleEndian(span[34..], 16); // bits per sample
        "data"u8.CopyTo(span[36..]);
        BinaryPrimitives.WriteInt32LittleEndian(span[40..], data);
        for (var i = 0; i < samples.Count; i++)
        {
            BinaryPrimitives.WriteInt16LittleEndian(span[(44 + (2 * i))..], samples[i]);
        }

        return wave;
    }
}
