using System.IO;
using System.Media;
using OperatorPanel.Core.Alarms;
using OperatorPanel.ViewModels.Alarms;
using OperatorPanel.ViewModels.Services;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// Plays the alarm tones (AlarmTone's WAVs, made in memory, so they do not depend on the Windows sound scheme) through
/// Windows' SoundPlayer, asynchronously. A PC without a sound device plays nothing and says so once in the log.
/// </summary>
public sealed class WpfAlarmSound(ILogger log) : IAlarmSound, IDisposable
{
    private readonly Dictionary<AlarmClass, SoundPlayer> _players = Enum.GetValues<AlarmClass>()
        .ToDictionary(c => c, c => new SoundPlayer(new MemoryStream(AlarmTone.Wave(c))));

    private bool _failed;

    public void Play(AlarmClass alarmClass)
    {
        try
        {
            _players[alarmClass].Play();
        }
        catch (InvalidOperationException ex)
        {
            Report(ex);
        }
    }

    public void Stop()
    {
        foreach (var player in _players.Values)
        {
            player.Stop();
        }
    }

    public void Dispose()
    {
        foreach (var player in _players.Values)
        {
            player.Dispose();
        }
    }

    private void Report(Exception ex)
    {
        if (!_failed)
        {
            _failed = true;
            log.Warning(ex, "The alarm sound could not be played (no sound device?); alarms are still shown");
        }
    }
}
